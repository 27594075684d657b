"""The climbing simulator: MuJoCo through dm-control, a gait planner, a whole-body controller.

Data flow: robot spec -> `scene.mjcf` (MJCF via MjSpec) on a `scene.arena` -> `scene.task`
(dm-control Physics, Task, `load`) -> `gait` targets -> `control` (QP, leg kinematics, servo)
-> `climb.rollout` (raw columns; the compiled loop in `climb.kernel`) -> `check` / `bench` /
`symmetry`; `tracking` runs learned models as controllers. `scene.setup.Climb` holds one
climb in numbers; `scene.layout` maps legs to model indices. Nothing here is imported by
`symbench --help`.
"""

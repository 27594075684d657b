"""The climbing simulator: MuJoCo through dm-control, a gait planner, a whole-body controller.

Data flow: robot spec -> `model` (MJCF via MjSpec) on an `arena` -> `task` (dm-control
Physics, Task, `load`) -> `gait` targets -> `controller` (QP in `qp`, leg `kinematics`) ->
`rollout` (raw columns) -> `check` / `bench` / `symmetry`. `setup.Climb` holds one climb in
numbers; `layout` maps legs to model indices. Nothing here is imported by `symbench --help`.
"""

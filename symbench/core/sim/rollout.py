"""Run the controller in the climbing environment and record raw trajectories.

Per physics step (1 kHz): read the state x_t (stepping as dm-control does, mj_step2 then
mj_step1, keeps position- and velocity-dependent quantities of x_t up to date), compute the
servo commands (every control period), record x_t, step, then record what the step did.
MuJoCo's implicit integrator applies the servo damping (and the ankle dampers) at the end-
of-step velocity, so the torque the joints really received is clip(u - Kp q_t - Kd qd_t+1)
and the acceleration they really had is (qd_t+1 - qd_t) / dt: those are recorded, so that
tau and qdd obey the same dynamics (`data.qacc`, the explicit forward acceleration, would
not). base_linacc likewise is the change of the base origin's world velocity over the
step, which excludes gravity. Rows are kept every `record_period` seconds.

Torque noise (`torque_noise` > 0, data for control): at every control step the servos
receive the expert's command plus Gaussian noise (per joint, std `torque_noise` N m, drawn
from `noise_seed`), which MuJoCo's actuator then clips like any command; the recorded `tau`
stays clip(u - Kp q_t - Kd qd_t+1) with u the expert's command without the noise: the
expert's answer at the perturbed state, not what perturbed it. With 0 the loop is exactly
the noise-free one.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from symbench.core.common.errors import SymbenchError
from symbench.core.sim.controller import ControlOutput, WholeBodyController
from symbench.core.sim.failure import detachment
from symbench.core.sim.gait import STANCE, SWING
from symbench.core.sim.model import SOLE_MARGIN
from symbench.core.sim.raw import validate_raw
from symbench.core.sim.scenario import Scenario
from symbench.core.sim.setup import Climb


@dataclass
class Rollout:
    arrays: dict[str, np.ndarray]  # exactly the columns of symbench/core/sim/raw.py
    attached: bool  # False when a stance foot left the surface or the base fell
    failure: str | None  # what went wrong, when it did
    metrics: dict[str, float] = field(default_factory=dict)  # tracking, torque, timing


class _Recorder:
    """Pre-allocated raw columns, filled row by row."""

    def __init__(self, n_rows: int, n_legs: int):
        shapes = {
            "t": (),
            "base_pos": (3,),
            "base_quat": (4,),
            "base_linvel": (3,),
            "base_angvel": (3,),
            "base_linacc": (3,),
            "q": (n_legs, 3),
            "qd": (n_legs, 3),
            "qdd": (n_legs, 3),
            "tau": (n_legs, 3),
            "contact": (n_legs,),
            "magnet": (n_legs,),
        }
        self.cols = {k: np.zeros((n_rows, *s)) for k, s in shapes.items()}
        self.rows = 0

    def trimmed(self) -> dict[str, np.ndarray]:
        return {k: v[: self.rows] for k, v in self.cols.items()}


def _period_steps(period: float, timestep: float, what: str) -> int:
    k = round(period / timestep)
    if k < 1 or abs(k * timestep - period) > 1e-9:
        raise SymbenchError(f"{what} {period} s is not a multiple of the physics step {timestep} s")
    return k


def run_climb(
    climb: Climb,
    seconds: float,
    record_period: float = 0.006,
    on_step: Callable[[ControlOutput, object], None] | None = None,
    control_period: float | None = None,
    torque_noise: float = 0.0,
    noise_seed: list[int] | None = None,
) -> Rollout:
    """Simulate `climb` for `seconds`; stops early (attached=False) when the robot falls.

    The whole-body controller runs every `control_period` seconds (default: every physics
    step, the spec's timestep); between its calls the servos keep their command, their joint
    feedback runs at every physics step inside MuJoCo. `torque_noise` (N m) adds Gaussian
    noise, seeded by `noise_seed`, to the executed command at every control step; the
    recorded `tau` is the expert's command without it (see the module's docstring).
    """
    import mujoco

    from symbench.core.sim.task import load_climb

    env = load_climb(climb, time_limit=seconds + 1.0)
    env.reset()
    physics, task = env.physics, env.task
    model, data, lay = physics.model.ptr, physics.data.ptr, physics.layout
    spec = climb.spec
    controller = WholeBodyController(spec, model, lay, task.plan, climb.base_rotation)
    dt = model.opt.timestep
    n_steps = int(round(seconds / dt))
    every = _period_steps(record_period, dt, "record_period")
    control_every = _period_steps(control_period or dt, dt, "control_period")
    rec = _Recorder(n_steps // every + 1, spec.n_legs)
    cols = rec.cols
    normal, height0 = task.plan.normal, float(task.plan.base_start @ task.plan.normal)
    kp, kd, limit = spec.control.kp, spec.control.kd, spec.control.torque_limit
    failure = None
    stats = _Stats(-(-n_steps // control_every), spec.n_legs)
    probe, ctrl = lay.probe(model, data), data.ctrl  # bound once: read at every step
    noise = np.random.default_rng(noise_seed) if torque_noise else None
    wall, cpu = time.perf_counter(), time.process_time()
    for step in range(n_steps):
        t = data.time
        control, row = step % control_every == 0, rec.rows if step % every == 0 else -1
        if control or row >= 0:
            distance, clearance = probe.both()
            contact = distance < spec.magnet.contact_distance
        if control:
            out = controller(data, t, clearance < SOLE_MARGIN)
            ctrl[lay.motor] = out.command
            if noise is not None:  # executed: the command plus noise; recorded: the command
                ctrl[lay.motor] += noise.normal(0.0, torque_noise, out.command.shape)
            ctrl[lay.magnet] = out.magnet
            stats.update(out, data, lay, task.plan)
            failure = detachment(
                out.targets.phase == STANCE, contact, data, lay.base_body, normal, height0
            )
            if failure is not None:
                failure = f"t={t:.3f} s: {failure}"
                break
        if row >= 0:
            r_base = data.xmat[lay.base_body].reshape(3, 3)
            cols["t"][row] = t
            cols["base_pos"][row] = data.qpos[:3]
            cols["base_quat"][row] = data.qpos[3:7]
            cols["base_linvel"][row] = data.qvel[:3]
            cols["base_angvel"][row] = r_base @ data.qvel[3:6]
            cols["q"][row] = q_now = data.qpos[lay.qpos]
            cols["qd"][row] = qd_now = data.qvel[lay.dof]
            linvel_now = data.qvel[:3].copy()
            cols["contact"][row] = contact
            cols["magnet"][row] = out.magnet > 0.0
        # dm-control's (legacy) physics step without its per-step Python checks and
        # observations: finish x_t (step2), then bring x_t+1 up to date (step1)
        mujoco.mj_step2(model, data)
        mujoco.mj_step1(model, data)
        if on_step is not None:
            on_step(out, physics)
        if row >= 0:
            qd_next = data.qvel[lay.dof]
            cols["tau"][row] = np.clip(out.command - kp * q_now - kd * qd_next, -limit, limit)
            cols["qdd"][row] = (qd_next - qd_now) / dt
            cols["base_linacc"][row] = (data.qvel[:3] - linvel_now) / dt
            rec.rows += 1
    wall, cpu = time.perf_counter() - wall, time.process_time() - cpu
    arrays = rec.trimmed()
    validate_raw(arrays, spec.n_legs, source=f"rollout of {spec.name}")
    metrics = stats.summary(spec, data, task.plan)
    metrics.update(
        sim_seconds=float(data.time),
        wall_seconds=wall,
        cpu_seconds=cpu,  # this process's CPU time: less distorted on a shared machine
        real_time_factor=float(data.time) / wall if wall > 0 else float("inf"),
        control_period=control_every * dt,
    )
    return Rollout(arrays, failure is None, failure, metrics)


class _Stats:
    """Tracking errors and torque peaks, for `symbench sim check`: the loop only stores
    rows (a few copies per control step), the errors are computed once at the end."""

    def __init__(self, n_rows: int, n_legs: int):
        self.base = np.zeros((n_rows, 2, 3))  # planned and measured base position
        self.swing = np.full((n_rows, 2, 3), np.nan)  # swing ankle target and position
        self.tau = np.zeros((n_rows, n_legs, 3))
        self.rows = 0
        self.start = None

    def update(self, out: ControlOutput, data, lay, plan) -> None:
        row = self.rows
        if self.start is None:
            self.start = data.qpos[:3].copy()
        tg = out.targets
        self.base[row, 0] = tg.base_pos
        self.base[row, 1] = data.qpos[:3]
        if tg.step_leg >= 0 and tg.phase[tg.step_leg] == SWING:
            self.swing[row, 0] = tg.sole_pos
            self.swing[row, 1] = data.xpos[lay.ankle_body[tg.step_leg]]
        self.tau[row] = out.tau
        self.rows += 1

    def summary(self, spec, data, plan) -> dict[str, float]:
        rows = self.rows
        base = np.linalg.norm(self.base[:rows, 0] - self.base[:rows, 1], axis=1)
        swinging = self.swing[:rows]
        swinging = swinging[~np.isnan(swinging[:, 0, 0])]
        target = swinging[:, 0] + spec.leg.lengths["foot"] * plan.normal
        swing = np.linalg.norm(target - swinging[:, 1], axis=1) if len(swinging) else np.zeros(1)
        magnitude = np.abs(self.tau[:rows])
        peak = magnitude.max(axis=(0, 1))
        clipped = int(np.count_nonzero(magnitude >= spec.control.torque_limit - 1e-9))
        walked = float((data.qpos[:3] - self.start) @ plan.direction)
        return {
            "distance_walked": walked,
            "base_error_rms": float(np.sqrt(np.mean(base**2))),
            "base_error_max": float(base.max()),
            "swing_error_rms": float(np.sqrt(np.mean(swing**2))),
            "swing_error_max": float(swing.max()),
            "peak_torque_coxa": float(peak[0]),
            "peak_torque_femur": float(peak[1]),
            "peak_torque_tibia": float(peak[2]),
            "torque_limit": float(spec.control.torque_limit),
            "clipped_fraction": clipped / max(magnitude.size, 1),
        }


def simulate(
    scenario: Scenario, record_period: float = 0.006, control_period: float | None = None
) -> Rollout:
    """The contract entry point: one scenario, raw columns every `record_period` seconds
    (controller every physics step unless `control_period` says otherwise)."""
    return run_climb(
        Climb.from_scenario(scenario),
        scenario.seconds,
        record_period,
        control_period=control_period,
        torque_noise=scenario.torque_noise,
        noise_seed=scenario.noise_seed() if scenario.torque_noise else None,
    )

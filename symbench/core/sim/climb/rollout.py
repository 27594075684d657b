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

A push (`Push`, the closed loop's perturbation): an external force on the base over some
physics steps, set between calls of the compiled loop (which then runs in segments around
the push); without one the loop is exactly the unpushed one.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np

from symbench.core.common.errors import SymbenchError
from symbench.core.sim.climb.kernel import climb_steps
from symbench.core.sim.contact.failure import Detachment, describe_fall
from symbench.core.sim.contact.kernel import HOLDING, QP_FAILED
from symbench.core.sim.control.controller import ControlOutput, WholeBodyController
from symbench.core.sim.gait.plan import STANCE, GaitPlan, GaitTargets
from symbench.core.sim.raw import RAW_COLUMNS, column_shape, validate_raw
from symbench.core.sim.scene.mjcf import SOLE_MARGIN
from symbench.core.sim.scene.push import Push
from symbench.core.sim.scene.scenario import Scenario
from symbench.core.sim.scene.setup import Climb

if TYPE_CHECKING:
    from symbench.core.robot.specs import RobotSpec


@dataclass
class Rollout:
    arrays: dict[str, np.ndarray]  # exactly the columns of symbench/core/sim/raw.py
    attached: bool  # False when a stance foot left the surface or the base fell
    failure: str | None  # what went wrong, when it did
    metrics: dict[str, float] = field(default_factory=dict)  # tracking, torque, timing


def _period_steps(period: float, timestep: float, what: str) -> int:
    k = round(period / timestep)
    if k < 1 or abs(k * timestep - period) > 1e-9:
        raise SymbenchError(f"{what} {period} s is not a multiple of the physics step {timestep} s")
    return k


def _raw_columns(n_rows: int, n_legs: int) -> dict[str, np.ndarray]:
    """Pre-allocated raw columns, in RAW_COLUMNS' order (the compiled loop's)."""
    return {c.name: np.zeros((n_rows, *column_shape(c, n_legs))) for c in RAW_COLUMNS}


def run_climb(
    climb: Climb,
    seconds: float,
    record_period: float = 0.006,
    on_step: Callable[[ControlOutput, object], None] | None = None,
    control_period: float | None = None,
    torque_noise: float = 0.0,
    noise_seed: list[int] | None = None,
    on_finish: Callable[[object], None] | None = None,
    push: Push | None = None,
) -> Rollout:
    """Simulate `climb` for `seconds`; stops early (attached=False) when the robot falls.

    The whole-body controller runs every `control_period` seconds (default: every physics
    step, the spec's timestep); between its calls the servos keep their command, their joint
    feedback runs at every physics step inside MuJoCo. `torque_noise` (N m) adds Gaussian
    noise, seeded by `noise_seed`, to the executed command at every control step; the
    recorded `tau` is the expert's command without it (see the module's docstring).
    `on_step(output, physics)`, when given, is called after every physics step (the loop
    then returns to Python at each step instead of running compiled throughout);
    `on_finish(physics)` once at the end. `push`, when given, acts on the base at its steps.
    """
    from symbench.core.sim.scene.task import load_climb

    env = load_climb(climb, time_limit=seconds + 1.0)
    env.reset()
    physics, task = env.physics, env.task
    model, data, lay = physics.model.ptr, physics.data.ptr, physics.layout
    spec, n = climb.spec, climb.spec.n_legs
    controller = WholeBodyController(spec, model, lay, task.plan, climb.base_rotation)
    dt = model.opt.timestep
    n_steps = int(round(seconds / dt))
    every = _period_steps(record_period, dt, "record_period")
    control_every = _period_steps(control_period or dt, dt, "control_period")
    n_control = -(-n_steps // control_every)
    cols = _raw_columns(n_steps // every + 1, n)
    stats = _Stats(n_control, n)
    out = (np.zeros(n, dtype=np.int64), np.zeros(n), *np.zeros((2, 3, 3)), *np.zeros((2, n, 3)))
    plan_step = np.zeros(2, dtype=np.int64)
    noise = (
        np.random.default_rng(noise_seed).normal(0.0, torque_noise, (n_control, n, 3))
        if torque_noise
        else np.zeros((0, n, 3))
    )
    normal, height0 = task.plan.normal, float(task.plan.base_start @ task.plan.normal)
    control = spec.control
    probe = lay.probe(model, data)
    args = (
        (dt, control_every, every, SOLE_MARGIN, spec.magnet.contact_distance),
        controller.kernel_args(data),
        out,
        plan_step,
        probe.kernel_args,
        Detachment(data, lay.base_body, normal, height0).limits,
        (data.qpos, data.qvel, data.qacc, data.xmat, data.xpos, data.ctrl),
        (
            *(np.ascontiguousarray(a, dtype=np.int64) for a in (lay.motor, lay.magnet)),
            *(np.ascontiguousarray(a, dtype=np.int64) for a in (lay.qpos, lay.dof)),
            int(lay.base_body),
            np.ascontiguousarray(lay.ankle_body, dtype=np.int64),
            control.kp,
            control.kd,
            control.torque_limit,
        ),
        noise,
        tuple(cols.values()),
        stats.arrays,
    )
    t0 = float(data.time)
    climb_steps(0, 0, t0, *args)  # no step: compiles or loads the loop outside the clocks
    wall, cpu = time.perf_counter(), time.process_time()
    window = push.steps(dt) if push is not None else range(0)
    force = push.world_force(task.plan.normal) if push is not None else np.zeros(3)
    applied = data.xfrc_applied[lay.base_body]  # a view: MuJoCo reads it at every step
    # compiled segments that start or stop where the push does, or one step at a time
    cuts = {min(max(k, 0), n_steps) for k in (window.start, window.stop)}
    stops = range(1, n_steps + 1) if on_step is not None else sorted((cuts | {n_steps}) - {0})
    steps, t, status = 0, t0, HOLDING
    for stop in stops:
        applied[:3] = force if steps in window else 0.0
        steps, t, status = climb_steps(steps, stop, t, *args)
        if status != HOLDING:
            break
        if on_step is not None:
            phase, magnet, base, sole, command, tau = (a.copy() for a in out)
            slot, leg = (int(v) for v in plan_step)
            targets = GaitTargets(phase, magnet, base, slot, leg, sole)
            on_step(ControlOutput(command, tau, magnet, targets), physics)
    applied[:3] = 0.0
    wall, cpu = time.perf_counter() - wall, time.process_time() - cpu
    if on_finish is not None:
        on_finish(physics)
    if t != data.time:
        raise SymbenchError(f"the loop's clock ({t} s) and MuJoCo's ({data.time} s) disagree")
    failure, control_rows = None, -(-steps // control_every)
    if status != HOLDING:  # stopped before step `steps` moved; its control row is kept
        contact = probe.sole_distances() < spec.magnet.contact_distance
        why = describe_fall(status, out[0] == STANCE, contact, data.qpos, normal)
        failure = f"t={t:.3f} s: {why}"
        control_rows = steps // control_every + (status != QP_FAILED)
    arrays = {k: v[: -(-steps // every)] for k, v in cols.items()}
    validate_raw(arrays, n, source=f"rollout of {spec.name}")
    metrics = stats.summary(spec, data, task.plan, control_rows)
    metrics.update(
        sim_seconds=float(data.time),
        wall_seconds=wall,
        cpu_seconds=cpu,  # this process's CPU time: less distorted on a shared machine
        real_time_factor=float(data.time) / wall if wall > 0 else float("inf"),
        control_period=control_every * dt,
    )
    return Rollout(arrays, failure is None, failure, metrics)


class _Stats:
    """Tracking errors and torque peaks, for `symbench sim check`: the loop fills a row per
    control step, the errors are computed once at the end."""

    def __init__(self, n_rows: int, n_legs: int):
        self.base = np.zeros((n_rows, 2, 3))  # planned and measured base position
        self.swing = np.full((n_rows, 2, 3), np.nan)  # swing ankle target and position
        self.tau = np.zeros((n_rows, n_legs, 3))
        self.arrays = (self.base, self.swing, self.tau)

    def summary(self, spec: RobotSpec, data: Any, plan: GaitPlan, rows: int) -> dict[str, float]:
        """The metrics over the first `rows` control steps."""
        base = np.linalg.norm(self.base[:rows, 0] - self.base[:rows, 1], axis=1)
        swinging = self.swing[:rows]
        swinging = swinging[~np.isnan(swinging[:, 0, 0])]
        target = swinging[:, 0] + spec.leg.lengths["foot"] * plan.normal
        swing = np.linalg.norm(target - swinging[:, 1], axis=1) if len(swinging) else np.zeros(1)
        magnitude = np.abs(self.tau[:rows])
        peak = magnitude.max(axis=(0, 1))
        clipped = int(np.count_nonzero(magnitude >= spec.control.torque_limit - 1e-9))
        walked = float((data.qpos[:3] - self.base[0, 1]) @ plan.direction)
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
    scenario: Scenario,
    record_period: float = 0.006,
    control_period: float | None = None,
    push: Push | None = None,
) -> Rollout:
    """The contract entry point: one scenario, raw columns every `record_period` seconds
    (controller every physics step unless `control_period` says otherwise), pushed when
    `push` is given."""
    return run_climb(
        Climb.from_scenario(scenario),
        scenario.seconds,
        record_period,
        control_period=control_period,
        torque_noise=scenario.torque_noise,
        noise_seed=scenario.noise_seed() if scenario.torque_noise else None,
        push=push,
    )

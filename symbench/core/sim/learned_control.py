"""A learned inverse-dynamics model as the robot's controller, tracking a reference climb.

The reference is the expert's climb recorded at every physics step (`expert_reference`):
its `tau` is the joint torque the servo really applied over each step (see rollout.py), so
replaying it reproduces the expert's trajectory to rounding, and the loop below actuates
exactly what that label means.

At every physics step (1 kHz) the policy gets two raw rows, as in the `next` variant: the
measured state now (what is not measured, the base acceleration, qdd and the magnet flags,
comes from the reference at the same time) and the desired state `lookahead` seconds
ahead (the record period the model was trained on). Its torque is the feedforward; a joint
PD at `pd_gains` about the desired state at the current time closes the loop. The magnets
get the gait plan's continuous command (the same ramp the expert used), rebuilt from the
scenario, which is deterministic.

Actuation. The simulated servo applies u - Kp q_t - Kd qd_t+1 (clipped), its damping taken
implicitly at the end-of-step velocity (model.py). The loop commands

    u = tau_ff + kp (q_ref,t - q_t) + Kp q_t + kd qd_ref,t+1 + (Kd - kd) (qd_t + dt qdd_ref,t)

with (kp, kd) the PD gains, so the applied torque is

    tau_ff + kp (q_ref,t - q_t) + kd (qd_ref,t+1 - qd_t+1) + (Kd - kd) dt (qdd_ref,t - qdd_t):

the feedforward, the PD (its damping, like the servo's, at the end of the step) and a
residual that vanishes whenever the joints accelerate as the reference did (it acts as an
apparent inertia (Kd - kd) dt, a few 1e-3 kg m^2, not as feedback on position or
velocity). On the reference the applied torque is exactly tau_ff: with the recorded tau as
feedforward the expert's command comes back to rounding, at every PD gain.

The robot counts as fallen when the base tilts or drops (as for the expert), when its base
is more than half a step length from the reference's (it lost its path: `off_path`), or when
a stance foot (magnet on in the reference) stays off the surface for more than GRACE_S: a
learned controller that lands a swing foot a few tens of milliseconds late has not fallen,
and the magnet pulls the foot in once it is within reach.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

from symbench.core.common.errors import SymbenchError
from symbench.core.sim.failure import Detachment, off_path
from symbench.core.sim.scenario import Scenario

GRACE_S = 0.1  # s a stance foot may stay off the surface before the climb counts as failed
LOOKAHEAD_S = 0.006  # s: the record period of the standard datasets (the `next` variant)

# per-sample policy: raw columns of two rows (now, desired ahead) -> torques (n_legs, 3); the
# rows are filled in place at every step, valid during the call only (copy what is kept)
Policy = Callable[[dict[str, np.ndarray]], np.ndarray]
# the raw columns row 0 takes from the simulation (the others come from the reference)
MEASURED = ("t", "base_pos", "base_quat", "base_linvel", "base_angvel", "q", "qd", "contact")
# called after every physics step with the dm-control Physics at the new time (read-only: a
# recorder for rendering, symbench.core.sim.render)
Observer = Callable[[Any], None]


@dataclass(frozen=True)
class Tracking:
    attached: bool
    failure: str | None
    time_to_failure_s: float  # the full horizon when it held on
    joint_rmse_rad: float  # against the reference, over the time it held on
    steps: int
    max_joint_error_rad: float = float("nan")  # over the time it held on
    base_drift_m: float = float("nan")  # base position error at the last step it held on
    base_drift_deg: float = float("nan")  # base orientation error then


def expert_reference(scenario: Scenario):
    """The expert's climb of `scenario` recorded at every physics step (a `Rollout`): the
    reference `track` needs. Its rows every 6 ms are the dataset's rows of the scenario."""
    from symbench.core.sim.rollout import simulate
    from symbench.core.sim.setup import Climb

    timestep = Climb.from_scenario(scenario).spec.control.timestep
    return simulate(scenario, record_period=timestep)


def _angle_deg(q1: np.ndarray, q2: np.ndarray) -> float:
    """The rotation angle between two orientations (w, x, y, z), in degrees."""
    w = float(q1[0] * q2[0] + q1[1:] @ q2[1:])
    v = q1[0] * q2[1:] - q2[0] * q1[1:] - np.cross(q1[1:], q2[1:])
    return float(np.degrees(2.0 * np.arctan2(np.linalg.norm(v), abs(w))))


def track(
    scenario: Scenario,
    reference: dict[str, np.ndarray],
    policy: Policy,
    pd_gains: tuple[float, float] = (0.0, 0.0),
    lookahead: float = LOOKAHEAD_S,
    observe: Observer | None = None,
) -> Tracking:
    """Run `policy` on `scenario` against `reference` (raw columns at every physics step,
    see `expert_reference`) over the reference's whole length; `observe`, when given, sees
    the physics after every step (it must not change it)."""
    import mujoco

    from symbench.core.sim.setup import Climb
    from symbench.core.sim.task import load_climb

    climb = Climb.from_scenario(scenario)
    spec = climb.spec
    dt = spec.control.timestep
    n_rows = len(reference["t"])
    if n_rows < 2 or abs(float(reference["t"][1] - reference["t"][0]) - dt) > 1e-9:
        raise SymbenchError(
            f"track: the reference must be recorded at every physics step ({dt} s); "
            "make it with expert_reference(scenario)"
        )
    ahead = max(1, int(round(lookahead / dt)))
    env = load_climb(climb, time_limit=n_rows * dt + 1.0)
    env.reset()
    physics, task = env.physics, env.task
    model, data, lay = physics.model.ptr, physics.data.ptr, physics.layout
    kp, kd, limit = spec.control.kp, spec.control.kd, spec.control.torque_limit
    pd_p, pd_d = pd_gains
    plan = task.plan
    normal, height0 = plan.normal, float(plan.base_start @ plan.normal)
    ref_q, ref_qd, ref_qdd = reference["q"], reference["qd"], reference["qdd"]
    stance_ref = reference["magnet"] > 0.5
    base_pos_ref = reference["base_pos"]
    errors = np.zeros((n_rows, *ref_q.shape[1:]))
    failure, last, pose = None, -1, np.zeros(7)
    off_steps = np.zeros(spec.n_legs, dtype=int)  # consecutive steps a stance foot is off
    grace = int(round(GRACE_S / dt))
    step_length = spec.gait.step_length
    # bound once (a MjData attribute read builds a new array object each time)
    probe, contact_distance = lay.probe(model, data), spec.magnet.contact_distance
    detachment = Detachment(data, lay.base_body, normal, height0)
    qpos, qvel, ctrl, xmat = data.qpos, data.qvel, data.ctrl, data.xmat
    joint_pos, joint_vel, motor, magnet, base_body = (
        lay.qpos,
        lay.dof,
        lay.motor,
        lay.magnet,
        lay.base_body,
    )
    # the policy's two rows, filled in place at every step (valid during the call only):
    # row 0 the measured state now (what is not measured, the base acceleration, qdd and
    # the magnet flags, is the desired motion from the reference), row 1 the desired state
    # `lookahead` ahead
    columns = [c for c in (*MEASURED, *reference) if c in reference]
    rows = {c: np.empty((2, *np.shape(reference[c])[1:])) for c in dict.fromkeys(columns)}
    unmeasured = [(rows[c], reference[c]) for c in rows if c not in MEASURED]
    ahead_rows = [(rows[c], reference[c]) for c in rows]
    for k in range(n_rows):
        t = data.time
        q, qd = qpos[joint_pos], qvel[joint_vel]
        contact = probe.sole_distances() < contact_distance
        off_steps = np.where(stance_ref[k] & ~contact, off_steps + 1, 0)
        off_too_long = off_steps > grace  # only these count as stance feet that left
        failure = detachment(off_too_long, ~off_too_long) or off_path(
            qpos[:3], base_pos_ref[k], step_length
        )
        if failure is not None:
            break
        last, pose = k, qpos[:7].copy()
        errors[k] = q - ref_q[k]
        j = min(k + ahead, n_rows - 1)
        for row, column in ahead_rows:
            row[1] = column[j]
        for row, column in unmeasured:
            row[0] = column[k]
        rows["t"][0] = t
        rows["base_pos"][0] = qpos[:3]
        rows["base_quat"][0] = qpos[3:7]
        rows["base_linvel"][0] = qvel[:3]
        rows["base_angvel"][0] = xmat[base_body].reshape(3, 3) @ qvel[3:6]  # world frame
        rows["q"][0] = q
        rows["qd"][0] = qd
        rows["contact"][0] = contact
        tau_ff = np.clip(np.asarray(policy(rows), dtype=np.float64), -limit, limit)
        qd_next = ref_qd[k + 1] if k + 1 < n_rows else ref_qd[k] + dt * ref_qdd[k]
        ctrl[motor] = (
            tau_ff
            + pd_p * (ref_q[k] - q)
            + kp * q
            + pd_d * qd_next
            + (kd - pd_d) * (qd + dt * ref_qdd[k])
        )
        ctrl[magnet] = plan.targets(t).magnet
        mujoco.mj_step2(model, data)
        mujoco.mj_step1(model, data)
        if observe is not None:
            observe(physics)
    held = float(data.time) if failure is not None else n_rows * dt
    if last < 0:
        return Tracking(False, failure, held, float("nan"), 0)
    held_errors = errors[: last + 1]
    drift = float(np.linalg.norm(pose[:3] - reference["base_pos"][last]))
    turn = _angle_deg(pose[3:7], reference["base_quat"][last])
    return Tracking(
        failure is None,
        failure,
        held,
        float(np.sqrt(np.mean(np.square(held_errors)))),
        last + 1,
        float(np.max(np.abs(held_errors))),
        drift,
        turn,
    )

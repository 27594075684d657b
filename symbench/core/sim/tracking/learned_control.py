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

A push (`Push`) acts on the base at the same physics steps as on the expert's climb of the
reference (`simulate(..., push=)`): tracked with the recorded torques, the pushed climb comes
back to rounding too.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from symbench.core.common.errors import SymbenchError
from symbench.core.sim.contact.failure import Detachment, off_path
from symbench.core.sim.scene.push import Push
from symbench.core.sim.scene.scenario import Scenario

GRACE_S = 0.1  # s a stance foot may stay off the surface before the climb counts as failed
LOOKAHEAD_S = 0.006  # s: the record period of the standard datasets (the `next` variant)
# rad: a step whose RMS joint error reaches this counts as lost as a step after a fall
# (`Tracking.tracking_cost`); about the error at which the PD alone loses the climb
ERROR_SCALE_RAD = 0.2

# per-sample policy: raw columns of two rows (now, desired ahead) -> torques (n_legs, 3); the
# rows are filled in place at every step, valid during the call only (copy what is kept)
Policy = Callable[[dict[str, np.ndarray]], np.ndarray]
# many samples at once (`track_batch`): rows 2i, 2i + 1 are sample i's two rows -> torques
# (n_samples, n_legs, 3)
BatchPolicy = Callable[[dict[str, np.ndarray]], np.ndarray]
# the raw columns row 0 takes from the simulation (the others come from the reference)
MEASURED = ("t", "base_pos", "base_quat", "base_linvel", "base_angvel", "q", "qd", "contact")
# called after every physics step with the dm-control Physics at the new time (read-only: a
# recorder for rendering, symbench.core.sim.tracking.render)
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
    # the mean over the horizon's steps of min(RMS joint error / ERROR_SCALE_RAD, 1), every
    # step after a fall counting 1: in [0, 1], continuous in the error and in the time held
    # (a fall one gait event later changes it by the steps gained, at their own error)
    tracking_cost: float = float("nan")


def expert_reference(scenario: Scenario):
    """The expert's climb of `scenario` recorded at every physics step (a `Rollout`): the
    reference `track` needs. Its rows every 6 ms are the dataset's rows of the scenario."""
    from symbench.core.sim.climb.rollout import simulate
    from symbench.core.sim.scene.setup import Climb

    timestep = Climb.from_scenario(scenario).spec.control.timestep
    return simulate(scenario, record_period=timestep)


def _angle_deg(q1: np.ndarray, q2: np.ndarray) -> float:
    """The rotation angle between two orientations (w, x, y, z), in degrees."""
    w = float(q1[0] * q2[0] + q1[1:] @ q2[1:])
    v = q1[0] * q2[1:] - q2[0] * q1[1:] - np.cross(q1[1:], q2[1:])
    return float(np.degrees(2.0 * np.arctan2(np.linalg.norm(v), abs(w))))


class _Rollout:
    """One tracking of a reference, stepped from outside so that many run in lockstep:
    `sense` checks the fall rules and fills the policy's rows for the current step, `act`
    actuates a feedforward torque and steps the physics, `result` sums it up."""

    def __init__(
        self,
        scenario: Scenario,
        reference: dict[str, np.ndarray],
        pd_gains: tuple[float, float],
        lookahead: float,
        observe: Observer | None,
        rows: dict[str, np.ndarray],
        push: Push | None = None,
    ):
        from symbench.core.sim.scene.setup import Climb
        from symbench.core.sim.scene.task import load_climb

        climb = Climb.from_scenario(scenario)
        spec = climb.spec
        self.dt = dt = spec.control.timestep
        self.n_rows = n_rows = len(reference["t"])
        if n_rows < 2 or abs(float(reference["t"][1] - reference["t"][0]) - dt) > 1e-9:
            raise SymbenchError(
                f"track: the reference must be recorded at every physics step ({dt} s); "
                "make it with expert_reference(scenario)"
            )
        self.ahead = max(1, int(round(lookahead / dt)))
        env = load_climb(climb, time_limit=n_rows * dt + 1.0)
        env.reset()
        self.physics, self.plan = env.physics, env.task.plan
        model, data, lay = self.physics.model.ptr, self.physics.data.ptr, self.physics.layout
        self.model, self.data, self.observe = model, data, observe
        self.kp, self.kd, self.limit = spec.control.kp, spec.control.kd, spec.control.torque_limit
        self.pd_p, self.pd_d = pd_gains
        normal, height0 = self.plan.normal, float(self.plan.base_start @ self.plan.normal)
        self.reference = reference
        self.stance_ref = reference["magnet"] > 0.5
        self.errors = np.zeros((n_rows, *reference["q"].shape[1:]))
        self.failure: str | None = None
        self.k, self.last, self.pose = -1, -1, np.zeros(7)
        self.off_steps = np.zeros(spec.n_legs, dtype=int)  # steps a stance foot is off
        self.grace = int(round(GRACE_S / dt))
        self.step_length = spec.gait.step_length
        # bound once (a MjData attribute read builds a new array object each time)
        self.probe, self.contact_distance = lay.probe(model, data), spec.magnet.contact_distance
        self.detachment = Detachment(data, lay.base_body, normal, height0)
        self.qpos, self.qvel, self.ctrl, self.xmat = data.qpos, data.qvel, data.ctrl, data.xmat
        self.joint_pos, self.joint_vel, self.motor, self.magnet, self.base_body = (
            lay.qpos,
            lay.dof,
            lay.motor,
            lay.magnet,
            lay.base_body,
        )
        self.window = push.steps(dt) if push is not None else range(0)
        self.force = push.world_force(self.plan.normal) if push is not None else np.zeros(3)
        self.applied = data.xfrc_applied[lay.base_body]  # a view MuJoCo reads at every step
        self.rows = rows
        self.unmeasured = [(rows[c], reference[c]) for c in rows if c not in MEASURED]
        self.ahead_rows = [(rows[c], reference[c]) for c in rows]

    def sense(self) -> bool:
        """Moves to the next step; False when the rollout is over (the whole reference
        tracked, or a fall); else the rows hold the policy's input for this step."""
        self.k = k = self.k + 1
        if k >= self.n_rows:
            return False
        qpos, qvel, rows = self.qpos, self.qvel, self.rows
        self.q, self.qd = q, qd = qpos[self.joint_pos], qvel[self.joint_vel]
        contact = self.probe.sole_distances() < self.contact_distance
        self.off_steps = np.where(self.stance_ref[k] & ~contact, self.off_steps + 1, 0)
        off_too_long = self.off_steps > self.grace  # only these count as stance feet that left
        self.failure = self.detachment(off_too_long, ~off_too_long) or off_path(
            qpos[:3], self.reference["base_pos"][k], self.step_length
        )
        if self.failure is not None:
            return False
        self.last, self.pose = k, qpos[:7].copy()
        self.errors[k] = q - self.reference["q"][k]
        j = min(k + self.ahead, self.n_rows - 1)
        for row, column in self.ahead_rows:
            row[1] = column[j]
        for row, column in self.unmeasured:
            row[0] = column[k]
        rows["t"][0] = self.data.time
        rows["base_pos"][0] = qpos[:3]
        rows["base_quat"][0] = qpos[3:7]
        rows["base_linvel"][0] = qvel[:3]
        rows["base_angvel"][0] = self.xmat[self.base_body].reshape(3, 3) @ qvel[3:6]  # world
        rows["q"][0] = q
        rows["qd"][0] = qd
        rows["contact"][0] = contact
        return True

    def act(self, tau_ff: np.ndarray) -> None:
        """Actuates feedforward `tau_ff` with the PD at this step and steps the physics."""
        import mujoco

        k, ref, dt = self.k, self.reference, self.dt
        q, qd = self.q, self.qd  # read by `sense` at this step: nothing moved since
        ref_qd, ref_qdd = ref["qd"], ref["qdd"]
        tau_ff = np.clip(np.asarray(tau_ff, dtype=np.float64), -self.limit, self.limit)
        qd_next = ref_qd[k + 1] if k + 1 < self.n_rows else ref_qd[k] + dt * ref_qdd[k]
        self.ctrl[self.motor] = (
            tau_ff
            + self.pd_p * (ref["q"][k] - q)
            + self.kp * q
            + self.pd_d * qd_next
            + (self.kd - self.pd_d) * (qd + dt * ref_qdd[k])
        )
        self.ctrl[self.magnet] = self.plan.targets(self.data.time).magnet
        self.applied[:3] = self.force if k in self.window else 0.0
        mujoco.mj_step2(self.model, self.data)
        mujoco.mj_step1(self.model, self.data)
        if self.observe is not None:
            self.observe(self.physics)

    def result(self) -> Tracking:
        failure, last, pose = self.failure, self.last, self.pose
        held = float(self.data.time) if failure is not None else self.n_rows * self.dt
        if last < 0:
            return Tracking(False, failure, held, float("nan"), 0, tracking_cost=1.0)
        held_errors = self.errors[: last + 1]
        per_step = np.sqrt(np.mean(np.square(held_errors.reshape(last + 1, -1)), axis=1))
        lost = np.sum(np.minimum(per_step / ERROR_SCALE_RAD, 1.0)) + (self.n_rows - last - 1)
        drift = float(np.linalg.norm(pose[:3] - self.reference["base_pos"][last]))
        turn = _angle_deg(pose[3:7], self.reference["base_quat"][last])
        return Tracking(
            failure is None,
            failure,
            held,
            float(np.sqrt(np.mean(np.square(held_errors)))),
            last + 1,
            float(np.max(np.abs(held_errors))),
            drift,
            turn,
            float(lost / self.n_rows),
        )


@dataclass(frozen=True)
class TrackJob:
    """One tracking of `track_batch`: a reference climb (see `expert_reference`) and the PD
    gains about it; `observe`, when given, sees the physics after every step; `push`, when
    given, acts on the base (the one the reference was climbed with)."""

    scenario: Scenario
    reference: dict[str, np.ndarray]
    pd_gains: tuple[float, float] = (0.0, 0.0)
    observe: Observer | None = None
    push: Push | None = None


def track_batch(
    jobs: Sequence[TrackJob], policy: BatchPolicy, lookahead: float = LOOKAHEAD_S
) -> list[Tracking]:
    """Run the jobs in lockstep, one `policy` call per physics step for all of them: row
    2i of its input is job i's measured state, row 2i + 1 its desired state `lookahead`
    ahead; it returns the feedforward torques (len(jobs), n_legs, 3). A job that is over
    keeps its last rows (its torque is ignored), so the policy always sees the same batch
    and a job's torques do not depend on when the others end. The jobs share the columns
    of their references (one robot)."""
    if not jobs:
        return []
    first = jobs[0].reference
    columns = [c for c in (*MEASURED, *first) if c in first]
    stacked = {
        c: np.zeros((2 * len(jobs), *np.shape(first[c])[1:])) for c in dict.fromkeys(columns)
    }
    rollouts = []
    for i, job in enumerate(jobs):
        if set(job.reference) != set(first):
            raise SymbenchError("track_batch: the references of one batch need the same columns")
        rows = {c: block[2 * i : 2 * i + 2] for c, block in stacked.items()}  # views
        rollouts.append(
            _Rollout(
                job.scenario, job.reference, job.pd_gains, lookahead, job.observe, rows, job.push
            )
        )
    live = [r.sense() for r in rollouts]
    while any(live):
        torques = policy(stacked)
        for i, rollout in enumerate(rollouts):
            if live[i]:
                rollout.act(torques[i])
                live[i] = rollout.sense()
    return [r.result() for r in rollouts]


def track(
    scenario: Scenario,
    reference: dict[str, np.ndarray],
    policy: Policy,
    pd_gains: tuple[float, float] = (0.0, 0.0),
    lookahead: float = LOOKAHEAD_S,
    observe: Observer | None = None,
    push: Push | None = None,
) -> Tracking:
    """Run `policy` on `scenario` against `reference` (raw columns at every physics step,
    see `expert_reference`) over the reference's whole length; `observe`, when given, sees
    the physics after every step (it must not change it); `push`, when given, acts on the
    base as it did on the expert's climb of the reference."""
    job = TrackJob(scenario, reference, pd_gains, observe, push)
    return track_batch([job], lambda rows: np.asarray(policy(rows))[None], lookahead)[0]

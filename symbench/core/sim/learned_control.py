"""A learned inverse-dynamics model as the robot's controller, tracking a reference climb.

At every control step (the physics step, 1 kHz) the model gets the measured state plus the
desired state one record period ahead (the `next` variant's q_next, qd_next, interpolated
from the reference, which is sampled every record period like the training data); the base
acceleration and the magnets come from the reference as the desired motion. Its torques,
clipped to the limits, are applied: the paper's inverse-dynamics controller. Optionally a
small PD term towards the same desired state is added (the paper's PD-augmented
comparison).

The robot counts as fallen when the base tilts or drops (as for the expert) or when a
stance foot (magnet on in the reference) stays off the surface for more than GRACE_S: a
learned controller that lands a swing foot a few tens of milliseconds late has not fallen,
and the magnet pulls the foot in once it is within reach.

The joint servos of the simulated robot are cancelled (u = tau + Kp q + Kd qd), so the
applied torque is the model's; only MuJoCo's implicit treatment of the servo damping
remains, a difference of Kd (qd_t - qd_t+1) per 1 ms step.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from symbench.core.sim.failure import detachment
from symbench.core.sim.scenario import Scenario

GRACE_S = 0.1  # s a stance foot may stay off the surface before the climb counts as failed

# per-sample policy: raw columns of two rows (now, reference next) -> torques (n_legs, 3)
Policy = Callable[[dict[str, np.ndarray]], np.ndarray]


@dataclass(frozen=True)
class Tracking:
    attached: bool
    failure: str | None
    time_to_failure_s: float  # the full duration when it held on
    joint_rmse_rad: float  # against the reference, over the time it held on
    steps: int


def _desired(reference: dict[str, np.ndarray], t: float, period: float) -> dict[str, np.ndarray]:
    """q and qd of the reference at time t (linear between its samples)."""
    s = t / period
    k = min(int(s), len(reference["t"]) - 2)
    a = s - k
    return {c: (1 - a) * reference[c][k] + a * reference[c][k + 1] for c in ("q", "qd")}


def track(
    scenario: Scenario,
    reference: dict[str, np.ndarray],
    policy: Policy,
    pd_gains: tuple[float, float] = (0.0, 0.0),
) -> Tracking:
    """Run `policy` on `scenario` against `reference` (raw columns every record period)."""
    import mujoco

    from symbench.core.sim.setup import Climb
    from symbench.core.sim.task import load_climb

    climb = Climb.from_scenario(scenario)
    n_rows = len(reference["t"])
    period = float(reference["t"][1] - reference["t"][0])
    duration = period * (n_rows - 2)  # the desired state one period ahead must exist
    env = load_climb(climb, time_limit=duration + 1.0)
    env.reset()
    physics, task = env.physics, env.task
    model, data, lay = physics.model.ptr, physics.data.ptr, physics.layout
    spec = climb.spec
    kp, kd, limit = spec.control.kp, spec.control.kd, spec.control.torque_limit
    pd_p, pd_d = pd_gains
    normal, height0 = task.plan.normal, float(task.plan.base_start @ task.plan.normal)
    errors, failure = [], None
    off_steps = np.zeros(spec.n_legs, dtype=int)  # consecutive steps a stance foot is off
    grace = int(round(GRACE_S / model.opt.timestep))
    for _ in range(int(round(duration / model.opt.timestep))):
        k = int(data.time / period + 1e-9)  # the reference sample now
        # what the robot measures (the observation's magnet column is only the last command)
        now = {**task.get_observation(physics), "t": np.array(data.time)}
        del now["magnet"]
        contact = now["contact"] > 0.5
        stance = reference["magnet"][k] > 0.5
        off_steps = np.where(stance & ~contact, off_steps + 1, 0)
        off_too_long = off_steps > grace  # only these count as stance feet that left
        failure = detachment(off_too_long, ~off_too_long, data, lay.base_body, normal, height0)
        if failure is not None:
            break
        errors.append(now["q"] - _desired(reference, data.time, period)["q"])
        target = _desired(reference, data.time + period, period)
        # measured state now; what is not measured (base acceleration, qdd, magnets) is the
        # desired motion from the reference, like the desired state one period ahead
        rows = {
            c: np.stack(
                [now[c] if c in now else reference[c][k], target.get(c, reference[c][k + 1])]
            )
            for c in reference
        }
        q, qd = now["q"], now["qd"]
        tau = np.asarray(policy(rows), dtype=np.float64)
        tau = np.clip(tau + pd_p * (target["q"] - q) + pd_d * (target["qd"] - qd), -limit, limit)
        data.ctrl[lay.magnet] = reference["magnet"][k]
        data.ctrl[lay.motor] = tau + kp * q + kd * qd
        mujoco.mj_step2(model, data)
        mujoco.mj_step1(model, data)
    held = float(data.time) if failure is not None else duration
    rmse = float(np.sqrt(np.mean(np.square(errors)))) if errors else float("nan")
    return Tracking(failure is None, failure, held, rmse, len(errors))

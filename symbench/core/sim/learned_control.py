"""A learned inverse-dynamics model as the robot's controller, tracking a reference climb.

Every record period (6 ms, the data's sample period) the model gets the measured state plus
the reference's state one period later (the `next` variant's q_next, qd_next; the base
acceleration and the magnets come from the reference too, as the desired motion) and its
torques, clipped to the limits, are held until the next period: the paper's inverse-dynamics
controller. Optionally a small PD term on the joint error is added (the paper's
PD-augmented comparison). The magnets follow the reference's schedule.

The joint servos of the simulated robot are cancelled (u = tau + Kp q + Kd qd), so the
applied torque is the model's; only MuJoCo's implicit treatment of the servo damping
remains, a difference of Kd (qd_t - qd_t+1) per 1 ms step.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from symbench.core.scenario import Scenario
from symbench.core.sim.failure import detachment

# per-sample policy: raw columns of two rows (now, reference next) -> torques (n_legs, 3)
Policy = Callable[[dict[str, np.ndarray]], np.ndarray]


@dataclass(frozen=True)
class Tracking:
    attached: bool
    failure: str | None
    time_to_failure_s: float  # the full duration when it held on
    joint_rmse_rad: float  # against the reference, over the time it held on
    steps: int


def _state_row(physics, contact: np.ndarray) -> dict[str, np.ndarray]:
    data, lay = physics.data, physics.layout
    r_base = data.xmat[lay.base_body].reshape(3, 3)
    return {"t": np.array(data.time), "base_pos": data.qpos[:3].copy(),
            "base_quat": data.qpos[3:7].copy(), "base_linvel": data.qvel[:3].copy(),
            "base_angvel": r_base @ data.qvel[3:6], "q": data.qpos[lay.qpos].copy(),
            "qd": data.qvel[lay.dof].copy(), "contact": contact.astype(np.float64)}


def track(scenario: Scenario, reference: dict[str, np.ndarray], policy: Policy,
          pd_gains: tuple[float, float] = (0.0, 0.0)) -> Tracking:
    """Run `policy` on `scenario` against `reference` (raw columns every record period)."""
    import mujoco

    from symbench.core.sim.setup import Climb
    from symbench.core.sim.task import load_climb

    climb = Climb.from_scenario(scenario)
    n_rows = len(reference["t"])
    period = float(reference["t"][1] - reference["t"][0])
    env = load_climb(climb, time_limit=period * n_rows + 1.0)
    env.reset()
    physics, task = env.physics, env.task
    model, data, lay = physics.model.ptr, physics.data.ptr, physics.layout
    spec = climb.spec
    every = int(round(period / model.opt.timestep))
    kp, kd, limit = spec.control.kp, spec.control.kd, spec.control.torque_limit
    pd_p, pd_d = pd_gains
    normal, height0 = task.plan.normal, float(task.plan.base_start @ task.plan.normal)
    errors, failure, k = [], None, 0
    for k in range(n_rows - 1):
        contact = physics.sole_distances() < spec.magnet.contact_distance
        stance = reference["magnet"][k] > 0.5
        failure = detachment(stance, contact, data, lay.base_body, normal, height0)
        if failure is not None:
            break
        now = _state_row(physics, contact)
        errors.append(now["q"] - reference["q"][k])
        # measured state now; what is not measured (base acceleration, qdd, magnets) is the
        # desired motion, taken from the reference, like the reference's next state
        rows = {c: np.stack([now[c] if c in now else reference[c][k], reference[c][k + 1]])
                for c in reference}
        tau_model = np.asarray(policy(rows), dtype=np.float64)
        data.ctrl[lay.magnet] = reference["magnet"][k]
        q_ref, qd_ref = reference["q"][k + 1], reference["qd"][k + 1]
        for _ in range(every):
            q, qd = data.qpos[lay.qpos], data.qvel[lay.dof]
            tau = np.clip(tau_model + pd_p * (q_ref - q) + pd_d * (qd_ref - qd), -limit, limit)
            data.ctrl[lay.motor] = tau + kp * q + kd * qd
            mujoco.mj_step2(model, data)
            mujoco.mj_step1(model, data)
    duration = period * (n_rows - 1)
    held = k * period if failure is not None else duration
    rmse = float(np.sqrt(np.mean(np.square(errors)))) if errors else float("nan")
    return Tracking(failure is None, failure, held, rmse, len(errors))

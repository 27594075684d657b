"""The whole-body controller's last compiled step (numba): from the QP's answer to the servo
command and the torque it applies now (see `kernel`, which calls it from `control_step`, on
why compiled code gives the same bits on every CPU)."""

from __future__ import annotations

import numpy as np
from numba import njit

from symbench.core.sim.control.kinematics import leg_ik_into


@njit(cache=True)
def servo_command(
    x,
    cons,
    mc_h_tau,
    jac,
    legs,
    inv_damped,
    ankle_ref,
    base_ref,
    sole_vel,
    swing,
    r_ref,
    rot_bl,
    org_bl,
    lengths,
    kp,
    kd,
    limit,
    command,
    tau,
):
    """The servo input u = tau_ff + Kp q_ref + Kd qd_ref and the torque it applies now,
    clip(u - Kp q - Kd qd); joint references from closed-form leg IK of the planned base
    and the ankle targets (stance: where the ankle is; swing: the spline), velocity
    references by damped least squares (safe at a stretched leg)."""
    n = legs.shape[0]
    nx = x.shape[0]
    tau_rows = cons.shape[0] - 3 * n
    target = np.empty(3)
    target_vel = np.empty(3)
    rel = np.empty(3)
    in_leg = np.empty(3)
    q_ref = np.empty(3)
    jtv = np.empty(3)
    for i in range(n):
        for k in range(3):
            if i == swing:
                target[k] = ankle_ref[k]
                target_vel[k] = -base_ref[1, k] + sole_vel[k]
            else:
                target[k] = legs[i, 0, k]
                target_vel[k] = -base_ref[1, k]
        for k in range(3):
            rel[k] = 0.0
        for c in range(3):
            for k in range(3):
                rel[c] += (target[k] - base_ref[0, k]) * r_ref[k, c]
        for c in range(3):
            in_leg[c] = 0.0
            for k in range(3):
                in_leg[c] += (rel[k] - org_bl[i, k]) * rot_bl[i, k, c]
        leg_ik_into(in_leg[0], in_leg[1], in_leg[2], lengths, q_ref)
        for c in range(3):
            jtv[c] = jac[i, 0, 6 + c] * target_vel[0] + jac[i, 1, 6 + c] * target_vel[1]
            jtv[c] += jac[i, 2, 6 + c] * target_vel[2]
        for r in range(3):
            s = mc_h_tau[3 * i + r]
            for k in range(nx):
                s += cons[tau_rows + 3 * i + r, k] * x[k]
            qd_ref = inv_damped[i, r, 0] * jtv[0] + inv_damped[i, r, 1] * jtv[1]
            qd_ref += inv_damped[i, r, 2] * jtv[2]
            u = s + kp * q_ref[r] + kd * qd_ref
            command[i, r] = u
            tau[i, r] = min(max(u - kp * legs[i, 2, r] - kd * legs[i, 3, r], -limit), limit)

"""The climbing loop, compiled: controller, servo commands, recording and MuJoCo's step
without a return to Python between physics steps (see `rollout` for what is recorded and
why; `native` for the C calls). Python's per-step overhead (a dozen calls, each building
array objects) cost as much as the physics; here the loop costs the controller's arithmetic,
DAQP and MuJoCo.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from symbench.core.sim.climb import native
from symbench.core.sim.contact.kernel import HOLDING, QP_FAILED, hold_state, surface_gaps
from symbench.core.sim.control.kernel import control_step
from symbench.core.sim.gait.kernel import STANCE, SWING


@njit(cache=True)
def climb_steps(
    start, stop, t, timing, controller, out, plan_step, probe, fall, mj, lay, noise, rec, stats
):
    """Run physics steps start .. stop-1 from time t; returns (steps done, time, status).

    timing = (dt, control every k steps, record every k steps, sole margin, contact
    distance); controller: `WholeBodyController.kernel_args`; out: the controller's output
    arrays (see `control_step`), kept between calls, and plan_step its last [slot, leg];
    probe: `surface_gaps`' arguments
    before its outputs; fall = (normal, min height, cos tilt limit); mj = MjData views
    (qpos, qvel, qacc, xmat, xpos, ctrl); lay = (motor ids (n, 3), magnet ids, qpos and dof
    addresses (n, 3), base body, ankle bodies, servo kp, kd, torque limit); noise (control
    steps, n, 3) added to the executed command (empty: none); rec: the raw columns in
    `raw.RAW_COLUMNS` order; stats
    = (planned and measured base, swing target and ankle, tau) per control step. Status:
    HOLDING, or why it stopped early (a fall, or QP_FAILED) at the returned step.
    """
    dt, control_every, record_every, sole_margin, contact_distance = timing
    model, data = controller[0], controller[1]
    phase, magnet, base, sole, command, tau = out
    qpos, qvel, qacc, xmat, xpos, ctrl = mj
    motor, magnet_ids, qpos_idx, dof_idx, base_body, ankle_body, kp, kd, limit = lay
    normal, min_height, cos_tilt = fall
    t_col, base_pos, base_quat, base_linvel, base_angvel, base_linacc = rec[:6]
    q_col, qd_col, qdd_col, tau_col, contact_col, magnet_col = rec[6:]
    planned, swing, tau_stat = stats
    n = phase.shape[0]
    distance, clearance = np.empty(n), np.empty(n)
    touching, contact = np.zeros(n, dtype=np.bool_), np.zeros(n, dtype=np.bool_)
    stance = np.zeros(n, dtype=np.bool_)
    q_now, qd_now, linvel_now = np.empty((n, 3)), np.empty((n, 3)), np.empty(3)
    for step in range(start, stop):
        control = step % control_every == 0
        row = step // record_every if step % record_every == 0 else -1
        if control or row >= 0:
            surface_gaps(*probe, distance, clearance)
            for i in range(n):
                contact[i] = distance[i] < contact_distance
                touching[i] = clearance[i] < sole_margin
        if control:
            c = step // control_every
            slot, leg, status = control_step(t, touching, *controller, out)
            if status < 1:
                return step, t, QP_FAILED
            plan_step[0], plan_step[1] = slot, leg
            for i in range(n):
                for k in range(3):
                    ctrl[motor[i, k]] = command[i, k] + (noise[c, i, k] if noise.size else 0.0)
                ctrl[magnet_ids[i]] = magnet[i]
                stance[i] = phase[i] == STANCE
                for k in range(3):
                    tau_stat[c, i, k] = tau[i, k]
            for k in range(3):
                planned[c, 0, k] = base[0, k]
                planned[c, 1, k] = qpos[k]
                if leg >= 0 and phase[leg] == SWING:
                    swing[c, 0, k] = sole[0, k]
                    swing[c, 1, k] = xpos[ankle_body[leg], k]
            status = hold_state(
                qacc, qpos, xmat, base_body, stance, contact, normal, min_height, cos_tilt
            )
            if status != HOLDING:
                return step, t, status
        if row >= 0:
            t_col[row] = t
            r_base = xmat[base_body].reshape((3, 3))
            for k in range(3):
                base_pos[row, k] = qpos[k]
                base_linvel[row, k] = qvel[k]
                linvel_now[k] = qvel[k]
                base_angvel[row, k] = r_base[k, 0] * qvel[3] + r_base[k, 1] * qvel[4]
                base_angvel[row, k] += r_base[k, 2] * qvel[5]
            for k in range(4):
                base_quat[row, k] = qpos[3 + k]
            for i in range(n):
                contact_col[row, i] = contact[i]
                magnet_col[row, i] = magnet[i] > 0.0
                for k in range(3):
                    q_col[row, i, k] = q_now[i, k] = qpos[qpos_idx[i, k]]
                    qd_col[row, i, k] = qd_now[i, k] = qvel[dof_idx[i, k]]
        # finish x_t (step2), then bring x_t+1 up to date (step1), as dm-control steps
        native.mj_step2(model, data)
        native.mj_step1(model, data)
        t += dt  # as MuJoCo advances its clock (the caller checks they agree)
        if row >= 0:
            for i in range(n):
                for k in range(3):
                    qd_next = qvel[dof_idx[i, k]]
                    torque = command[i, k] - kp * q_now[i, k] - kd * qd_next
                    tau_col[row, i, k] = min(max(torque, -limit), limit)
                    qdd_col[row, i, k] = (qd_next - qd_now[i, k]) / dt
            for k in range(3):
                base_linacc[row, k] = (qvel[k] - linvel_now[k]) / dt
    return stop, t, HOLDING

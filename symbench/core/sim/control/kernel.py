"""The whole-body controller's arithmetic, compiled (numba): the QP's data from the state,
and the servo command from the QP's answer (`servo_command`, in `servo`).

Why compiled: the controller runs at every 1 kHz physics step, and as numpy code its
~150 calls on 3-vectors and 3 x 3 blocks cost ten times MuJoCo's own step. Here each leg's
Jacobian, inverses and products are plain loops over fixed small sizes, in IEEE double
arithmetic without fast-math (no reassociation, no contraction into FMA): on the pinned
generator (`NUMBA_CPU_NAME=generic`, see `symbench.core.data.generation.determinism`) the
machine code is the same on every x86-64 CPU, and so are the results.

Layout (see `controller`): x = [base acc (6), swing joint acc (3), foot forces (3n)];
constraint rows = [6 floating-base equations | 5 pyramid rows per foot | 3 torque rows per
leg]; `jac[i]` (3, 9) is leg i's world ankle Jacobian on [base dofs (6) | its joints (3)].
"""

from __future__ import annotations

import numpy as np
from numba import njit

from symbench.core.sim.climb import native
from symbench.core.sim.control.qp import solve_in_place
from symbench.core.sim.control.servo import servo_command
from symbench.core.sim.gait.kernel import RELEASE, SWING, TOUCHDOWN, gait_targets

QP_INF = 1e30  # an absent bound (the QP solver's infinity)

# gains: indices into the float parameter vector built by the controller
BASE_KP, BASE_KD, SWING_KP, SWING_KD, STANCE_KD, W_TASK = 0, 1, 2, 3, 4, 5
W_FORCE, W_RELEASE, IK_DAMPING_SQ, FOOT, PRESS, MU, PULL = 6, 7, 8, 9, 10, 11, 12
N_GAINS = 13


@njit(cache=True, inline="always")
def _inverse3(m, out):
    """out = m^-1 for a 3 x 3 matrix, by the adjugate (row k of the cofactors is
    row k+1 x row k+2)."""
    for k in range(3):
        a, b = (k + 1) % 3, (k + 2) % 3
        for j in range(3):
            j1, j2 = (j + 1) % 3, (j + 2) % 3
            out[j, k] = m[a, j1] * m[b, j2] - m[a, j2] * m[b, j1]
    det = m[0, 0] * out[0, 0] + m[0, 1] * out[1, 0] + m[0, 2] * out[2, 0]
    for k in range(3):
        for j in range(3):
            out[j, k] /= det


@njit(cache=True, inline="always")
def _cross_into(a, b, out, col):
    """out[:, col] = a x b."""
    out[0, col] = a[1] * b[2] - a[2] * b[1]
    out[1, col] = a[2] * b[0] - a[0] * b[2]
    out[2, col] = a[0] * b[1] - a[1] * b[0]


@njit(cache=True)
def qp_problem(
    m_full,
    qfrc_bias,
    qpos,
    qvel,
    xpos,
    xaxis,
    xanchor,
    xmat,
    reduced,
    joints,
    qpos_idx,
    dof_idx,
    ankle_body,
    base_body,
    gains,
    r_ref,
    normal,
    h_base,
    tau_max,
    base_ref,
    sole_ref,
    magnet,
    swing,
    touchdown,
    release_leg,
    hess,
    grad,
    cons,
    lower,
    upper,
    jac,
    legs,
    inv_damped,
    mc_h_tau,
    ankle_ref,
):
    """Fill the QP (hess, grad, cons, lower, upper) of one control step.

    base_ref rows: planned base position, velocity, acceleration; sole_ref rows: the
    stepping sole's target position, velocity, acceleration. `swing` is the leg whose
    ankle is tracked (-1: none), `touchdown` whether it is pressing on to touch down,
    `release_leg` the leg whose magnet is being released (-1: none). Also left for
    `servo_command`: jac, legs ([ankle, ankle velocity, q, qd] per leg), the damped IK
    inverses, M c + h of the torque rows and the swing ankle's target.
    """
    n = joints.shape[0]
    nr = reduced.shape[0]
    r_base = xmat[base_body].reshape((3, 3))
    w_task = gains[W_TASK]

    # per leg: state, ankle Jacobian (columns: axis x (ankle - point on the axis)), velocity
    axis = np.empty(3)
    lever = np.empty(3)
    for i in range(n):
        a = ankle_body[i]
        for k in range(3):
            legs[i, 0, k] = xpos[a, k]
            legs[i, 2, k] = qpos[qpos_idx[i, k]]
            legs[i, 3, k] = qvel[dof_idx[i, k]]
        for r in range(3):
            for col in range(3):
                jac[i, r, col] = 1.0 if r == col else 0.0
        for m in range(3):  # base rotation axes (MuJoCo's local angular velocity)
            for k in range(3):
                axis[k] = r_base[k, m]
                lever[k] = legs[i, 0, k] - qpos[k]
            _cross_into(axis, lever, jac[i], 3 + m)
        for j in range(3):
            jt = joints[i, j]
            for k in range(3):
                axis[k] = xaxis[jt, k]
                lever[k] = legs[i, 0, k] - xanchor[jt, k]
            _cross_into(axis, lever, jac[i], 6 + j)
        for r in range(3):
            v = 0.0
            for col in range(6):
                v += jac[i, r, col] * qvel[col]
            for j in range(3):
                v += jac[i, r, 6 + j] * legs[i, 3, j]
            legs[i, 1, r] = v

    # stance legs follow the base: qdd_leg = J_leg^-1 (-J_base a - kd ankle velocity),
    # so qdd_r = [a; the legs' rows of T a + c], T (nr, 6) and c zero on the base's rows;
    # the swing leg's joint accelerations are variables of their own (columns 6-8)
    transfer = np.zeros((nr, 6))
    offset = np.zeros(nr)
    jl = np.empty((3, 3))
    jl_inv = np.empty((3, 3))
    normal_eq = np.empty((3, 3))
    for i in range(n):
        for r in range(3):
            for c in range(3):
                jl[r, c] = jac[i, r, 6 + c]
        _inverse3(jl, jl_inv)
        for r in range(3):
            for c in range(3):
                s = 0.0
                for k in range(3):
                    s += jl[k, r] * jl[k, c]
                normal_eq[r, c] = s + (gains[IK_DAMPING_SQ] if r == c else 0.0)
        _inverse3(normal_eq, inv_damped[i])
        if i == swing:
            continue
        row = 6 + 3 * i
        for r in range(3):
            for col in range(6):
                s = 0.0
                for k in range(3):
                    s += jl_inv[r, k] * jac[i, k, col]
                transfer[row + r, col] = -s
            s = 0.0
            for k in range(3):
                s += jl_inv[r, k] * (-gains[STANCE_KD] * legs[i, 1, k])
            offset[row + r] = s

    # objective: base pose and swing ankle tracking, regularisation, force weights
    hess[:, :] = h_base
    grad[:] = 0.0
    e = np.empty((3, 3))  # R_ref R', whose skew part is the small-angle orientation error
    for r in range(3):
        for c in range(3):
            e[r, c] = r_ref[r, 0] * r_base[c, 0] + r_ref[r, 1] * r_base[c, 1]
            e[r, c] += r_ref[r, 2] * r_base[c, 2]
    vee = np.empty(3)
    vee[0] = 0.5 * (e[2, 1] - e[1, 2])
    vee[1] = 0.5 * (e[0, 2] - e[2, 0])
    vee[2] = 0.5 * (e[1, 0] - e[0, 1])
    a_ang = np.empty(3)
    for k in range(3):
        omega = r_base[k, 0] * qvel[3] + r_base[k, 1] * qvel[4] + r_base[k, 2] * qvel[5]
        a_ang[k] = gains[BASE_KP] * vee[k] - gains[BASE_KD] * omega
        a_lin = (
            base_ref[2, k]
            + gains[BASE_KP] * (base_ref[0, k] - qpos[k])
            + gains[BASE_KD] * (base_ref[1, k] - qvel[k])
        )
        grad[k] = -w_task * a_lin
    for k in range(3):
        grad[3 + k] = -w_task * (
            r_base[0, k] * a_ang[0] + r_base[1, k] * a_ang[1] + r_base[2, k] * a_ang[2]
        )
    if swing >= 0:
        reach = gains[FOOT] - (gains[PRESS] if touchdown else 0.0)
        a_sw = np.empty(3)
        for k in range(3):
            ankle_ref[k] = sole_ref[0, k] + reach * normal[k]
            a_sw[k] = (
                sole_ref[2, k]
                + gains[SWING_KP] * (ankle_ref[k] - legs[swing, 0, k])
                + gains[SWING_KD] * (sole_ref[1, k] - legs[swing, 1, k])
            )
        js = jac[swing]
        for r in range(9):
            for c in range(9):
                hess[r, c] += w_task * (
                    js[0, r] * js[0, c] + js[1, r] * js[1, c] + js[2, r] * js[2, c]
                )
            grad[r] -= w_task * (js[0, r] * a_sw[0] + js[1, r] * a_sw[1] + js[2, r] * a_sw[2])
    for i in range(n):
        weight = gains[W_RELEASE] if i == release_leg else gains[W_FORCE]
        for k in range(3):
            hess[9 + 3 * i + k, 9 + 3 * i + k] += weight

    # dynamics: M_r qdd_r + h_r = S' tau + sum_i J_i' f_i, with qdd_r as above
    m_r = np.empty((nr, nr))
    for r in range(nr):
        for k in range(nr):
            m_r[r, k] = m_full[reduced[r], reduced[k]]
    mc_h = np.empty(nr)
    for r in range(nr):
        row = r if r < 6 else 5 * n + r
        s = qfrc_bias[reduced[r]]
        for k in range(6, nr):
            s += m_r[r, k] * offset[k]
        mc_h[r] = s
        for col in range(6):
            s = m_r[r, col]
            for k in range(6, nr):
                s += m_r[r, k] * transfer[k, col]
            cons[row, col] = s
        for j in range(3):
            cons[row, 6 + j] = m_r[r, 6 + 3 * swing + j] if swing >= 0 else 0.0
    for r in range(6):  # the base rows see every foot's force; the leg rows only their own
        for i in range(n):
            for k in range(3):
                cons[r, 9 + 3 * i + k] = -jac[i, k, r]
        lower[r] = upper[r] = -mc_h[r]
    tau_rows = 6 + 5 * n
    for i in range(n):
        down = i != swing
        pull = gains[PULL] * magnet[i] * (1.0 if down else 0.0)
        for k in range(4):  # friction pyramid, widened by the pull
            lower[6 + 5 * i + k] = -QP_INF
            upper[6 + 5 * i + k] = gains[MU] * pull
        lower[6 + 5 * i + 4] = -pull  # normal force: the surface pushes, the magnet pulls
        upper[6 + 5 * i + 4] = QP_INF if down else 0.0
        for r in range(3):
            row = tau_rows + 3 * i + r
            mc_h_tau[3 * i + r] = mc_h[6 + 3 * i + r]
            for j in range(n):
                for k in range(3):
                    cons[row, 9 + 3 * j + k] = -jac[i, k, 6 + r] if j == i else 0.0
            lower[row] = -tau_max[r] - mc_h[6 + 3 * i + r]
            upper[row] = tau_max[r] - mc_h[6 + 3 * i + r]


@njit(cache=True)
def control_step(t, touching, model, data, state, layout, plan, fixed, liftoff, work, qp, out):
    """One call of the whole-body controller at time t (`controller` packs the tuples):
    the gait plan's targets, the QP, and the servo command. `touching` says which soles are
    close enough for the magnet; `liftoff` = [slot, sole position] of the last magnet
    release, kept between calls. Fills out = (phase, magnet, base, sole, command, tau) and
    returns (slot, stepping leg, QP exit flag); a flag below 1 means no command: the QP had
    no solution even without torque limits."""
    phase, magnet, base, sole, command, tau = out
    gains, r_ref, h_base, tau_max, rot_bl, org_bl, lengths, servo = fixed
    _, _, cons, lower, upper, jac, legs, inv_damped, mc_h_tau, ankle_ref = work
    normal = plan[5]
    liftoff_slot = int(liftoff[0])
    slot, step_leg = gait_targets(t, *plan, liftoff[1:], liftoff_slot, phase, magnet, base, sole)
    step_phase = phase[step_leg] if step_leg >= 0 else 0
    if step_phase == RELEASE:  # where the foot stands
        liftoff[0] = slot
        ankle = layout[4][step_leg]
        for k in range(3):
            liftoff[1 + k] = state[4][ankle, k] - gains[FOOT] * normal[k]
    # the stepping leg is tracked while swinging and, pressing on, until it touches down
    lifted = step_phase == SWING or (step_phase == TOUCHDOWN and not touching[step_leg])
    swing = step_leg if lifted else -1
    native.mj_full_m(model, data, state[0].ctypes.data)
    touchdown = step_phase == TOUCHDOWN
    release_leg = step_leg if step_phase == RELEASE else -1
    qp_problem(
        *state,
        *layout,
        gains,
        r_ref,
        normal,
        h_base,
        tau_max,
        base,
        sole,
        magnet,
        swing,
        touchdown,
        release_leg,
        *work,
    )
    status = solve_in_place(qp)
    if status < 1:  # torque limits cannot be met: solve without, clip afterwards
        tau_rows = cons.shape[0] - 3 * legs.shape[0]
        lower[tau_rows:] = -QP_INF
        upper[tau_rows:] = QP_INF
        status = solve_in_place(qp)
        if status < 1:
            return slot, step_leg, status
    servo_command(
        qp[1][-1],
        cons,
        mc_h_tau,
        jac,
        legs,
        inv_damped,
        ankle_ref,
        base,
        sole[1],
        swing,
        r_ref,
        rot_bl,
        org_bl,
        lengths,
        servo[0],
        servo[1],
        servo[2],
        command,
        tau,
    )
    return slot, step_leg, status

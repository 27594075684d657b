"""Whole-body controller: task-space inverse dynamics as a QP, then joint feedback.

Every control step:
1. The QP tracks the base pose and the swing ankle with task accelerations. Its variables
   are the base acceleration, the swing leg's joint accelerations and the force that the
   surface plus the magnet exert on each foot; the stance legs' joint accelerations follow
   from zero (damped) stance-ankle acceleration. Constraints: the floating-base rows of
   M qdd + h = S'tau + J'f, friction pyramids widened by the magnet pull
   (|f_t| <= mu (f_n + F_magnet)), zero force on a lifted foot, and torque limits. M comes
   from mj_fullM, h from qfrc_bias, the ankle Jacobians from MuJoCo's joint axes and
   anchors (the passive gimbal passes the foot's force through the ankle; gimbal
   accelerations are taken as zero, and so are the Jacobians' velocity products, small at
   this gait's speeds).
2. Joint references from closed-form leg IK of the base reference and the ankle targets
   (stance: where the ankle is; swing: the spline).
3. Applied torque = feed-forward + Kp (q_ref - q) + Kd (qd_ref - qd), clipped to the limit;
   the feedback runs inside MuJoCo's actuator (symbench.core.sim.model) so that the
   implicit integrator keeps it stable, the controller sends u = tau_ff + Kp q_ref + Kd qd_ref.
The friction pyramid's tangent axes follow each leg's frame, so nothing depends on leg
numbering beyond relabelling: the whole loop is equivariant under the robot's rotations.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from symbench.core.robots import RobotSpec
from symbench.core.sim.gait import RELEASE, SWING, TOUCHDOWN, GaitPlan, GaitTargets
from symbench.core.sim.kinematics import leg_ik
from symbench.core.sim.layout import ModelLayout
from symbench.core.sim.model import ankle_to_sole
from symbench.core.sim.qp import INF, DenseQP, InfeasibleQP

LEVI_CIVITA = np.zeros((3, 3, 3))  # cross products as one einsum: (a x b)_i = e_ijk a_j b_k
LEVI_CIVITA[0, 1, 2] = LEVI_CIVITA[1, 2, 0] = LEVI_CIVITA[2, 0, 1] = 1.0
LEVI_CIVITA[0, 2, 1] = LEVI_CIVITA[2, 1, 0] = LEVI_CIVITA[1, 0, 2] = -1.0
IK_DAMPING = 1e-3  # m, damping of the velocity-level leg IK
PRESS = 0.01  # m: a foot still in the air at touchdown is driven this far into the surface


@dataclass(frozen=True)
class ControllerGains:
    """Controller settings that the robot spec does not fix (chosen here, see README)."""

    base_kp: float = 400.0  # 1/s^2, base position and orientation
    base_kd: float = 40.0
    swing_kp: float = 900.0
    swing_kd: float = 60.0
    stance_kd: float = 20.0  # damping of residual stance-ankle velocity
    w_task: float = 100.0
    w_qdd: float = 1e-2  # regularisation: makes the QP strictly convex
    w_force: float = 1e-3
    w_release: float = 1.0  # force weight on a foot whose magnet is being released
    friction_margin: float = 0.8  # fraction of mu used in the pyramid
    magnet_margin: float = 0.7  # fraction of the pull the QP may rely on
    torque_margin: float = 0.8  # fraction of the limit left to the feed-forward


@dataclass
class ControlOutput:
    command: np.ndarray  # (n, 3) servo input u = tau_ff + Kp q_ref + Kd qd_ref
    tau: np.ndarray  # (n, 3) torque the servo applies at this state: clip(u - Kp q - Kd qd)
    magnet: np.ndarray  # (n,)
    targets: GaitTargets


def _vee_error(r_ref: np.ndarray, r: np.ndarray) -> np.ndarray:
    """Small-angle orientation error (world frame) taking R to R_ref."""
    e = r_ref @ r.T
    return 0.5 * np.array([e[2, 1] - e[1, 2], e[0, 2] - e[2, 0], e[1, 0] - e[0, 1]])


class WholeBodyController:
    def __init__(self, spec: RobotSpec, model, layout: ModelLayout, plan: GaitPlan,
                 base_rotation: np.ndarray, gains: ControllerGains | None = None):
        self.spec, self.model, self.layout, self.plan = spec, model, layout, plan
        self.gains = gains or ControllerGains()
        self.r_ref = base_rotation
        n = spec.n_legs
        self.n, self.nr = n, 6 + 3 * n
        self.nx = 9 + 3 * n  # base acceleration (6), swing-leg joint acceleration (3), forces
        self.normal = plan.normal
        # per-leg pyramid axes: the leg's x (at the reference pose) in the surface plane
        leg_axes = np.einsum("ij,njk->nik", base_rotation, spec.leg_rotations())
        t1 = leg_axes[:, :, 0] - np.outer(leg_axes[:, :, 0] @ self.normal, self.normal)
        t1 /= np.linalg.norm(t1, axis=1, keepdims=True)
        t2 = np.cross(self.normal, t1)
        mu = spec.magnet.friction * self.gains.friction_margin
        # rows per leg: +-t1 - mu n, +-t2 - mu n (<= mu F), then n (>= -F)
        self.cone = np.stack([t1 - mu * self.normal, -t1 - mu * self.normal,
                              t2 - mu * self.normal, -t2 - mu * self.normal,
                              np.broadcast_to(self.normal, t1.shape)], axis=1)  # (n, 5, 3)
        self.mu = mu
        self.rot_bl = spec.leg_rotations()
        self.org_bl = spec.leg_origins()
        self.kp, self.kd = spec.control.kp, spec.control.kd
        self.limit = spec.torque_limits()
        self.foot = ankle_to_sole(spec)
        self.qp = DenseQP(self.nx, 6, 8 * n)
        self._m_full = np.zeros((model.nv, model.nv))
        self._red = np.ix_(layout.reduced, layout.reduced)
        self._C = np.zeros((8 * n, self.nx))
        rows = 5 * np.arange(n)[:, None, None] + np.arange(5)[None, :, None]
        cols = 9 + 3 * np.arange(n)[:, None, None] + np.arange(3)[None, None, :]
        self._C[rows, cols] = self.cone
        self._legs = np.arange(n)
        self._liftoff: tuple[int, np.ndarray | None] = (-1, None)  # (slot, sole at release)
        self._eye3, self._eye6 = np.eye(3), np.eye(6)
        self._tau_max = np.tile(self.limit * self.gains.torque_margin, n)
        self._jb = np.zeros((n, 3, 6))
        self._jb[:, :, :3] = np.eye(3)
        self._cone_rows = 5 * self._legs[:, None] + np.arange(5)[None, :]
        k3 = np.arange(3)
        self._tau_rows = (5 * n + 3 * self._legs[:, None, None] + k3[None, :, None]) + 0 * k3
        self._tau_cols = (9 + 3 * self._legs[:, None, None] + k3[None, None, :]) + 0 * k3[:, None]
        self._force_diag = np.arange(9, self.nx)
        self._h_base = np.zeros((self.nx, self.nx))  # the constant part of the Hessian
        self._h_base[:9, :9] = self.gains.w_qdd * np.eye(9)
        self._h_base[:6, :6] += self.gains.w_task * np.eye(6)  # |R a| = |a|: R is orthogonal

    def _ankle_jacobians(self, data, ankle: np.ndarray, r_base: np.ndarray):
        """World-frame ankle Jacobians w.r.t. the free joint (n, 3, 6; MuJoCo's velocity
        coordinates: world linear, local angular) and w.r.t. each leg's joints (n, 3, 3),
        from MuJoCo's joint axes and anchors: column = axis x (ankle - anchor)."""
        jb = self._jb.copy()
        arm = ankle - data.qpos[:3]
        jb[:, :, 3:] = np.einsum("ijk,jm,nk->nim", LEVI_CIVITA, r_base, arm)  # R e_m x arm
        joints = self.layout.joint
        lever = ankle[:, None, :] - data.xanchor[joints]
        jl = np.einsum("ijk,nmj,nmk->nim", LEVI_CIVITA, data.xaxis[joints], lever)
        return jb, jl

    def __call__(self, data, t: float, touching: np.ndarray) -> ControlOutput:
        """Torques at time t; `touching` says which soles are close enough for the magnet."""
        import mujoco

        g, n, nr, lay = self.gains, self.n, self.nr, self.layout
        slot = self.plan.slot_index(t)
        tg = self.plan.targets(t, self._liftoff[1] if self._liftoff[0] == slot else None)
        mujoco.mj_fullM(self.model, data, self._m_full)
        m_r = self._m_full[self._red]
        h_r = data.qfrc_bias[lay.reduced]
        qvel = data.qvel
        q = data.qpos[lay.qpos]
        qd = qvel[lay.dof]
        ankle = data.xpos[lay.ankle_body]
        r_base = data.xmat[lay.base_body].reshape(3, 3)
        if tg.step_leg >= 0 and tg.phase[tg.step_leg] == RELEASE:  # where the foot stands
            self._liftoff = (slot, ankle[tg.step_leg] - self.foot * self.normal)
        jb, jl = self._ankle_jacobians(data, ankle, r_base)
        ankle_vel = jb @ qvel[:6] + (jl @ qd[..., None])[..., 0]
        # the stepping leg is tracked while swinging and, pressing on, until it touches down
        swing = tg.step_leg if (tg.step_leg >= 0 and (tg.phase[tg.step_leg] == SWING or (
            tg.phase[tg.step_leg] == TOUCHDOWN and not touching[tg.step_leg]))) else -1

        # contact set: feet that are down (lifted only while swinging; touchdown once felt)
        down = (tg.phase != SWING) & ((tg.phase != TOUCHDOWN) | touching)
        pull = self.spec.magnet.force * g.magnet_margin * tg.magnet * down

        # qdd_r = T x + c: stance legs follow the base so that their ankles do not accelerate
        # (beyond damping their residual velocity); the swing leg's joints are variables.
        jl_inv = np.linalg.inv(jl)
        # A lifted foot that is not tracked (touchdown before contact) keeps qdd = 0.
        follows = (down & (self._legs != swing)).astype(float)[:, None, None]
        T = np.zeros((nr, self.nx))
        T[:6, :6] = self._eye6
        T[6:, :6] = (-(jl_inv @ jb) * follows).reshape(3 * n, 6)
        c = np.zeros(nr)
        c[6:] = ((jl_inv @ (-g.stance_kd * ankle_vel)[..., None]) * follows).reshape(-1)
        if swing >= 0:
            T[6 + 3 * swing: 9 + 3 * swing, 6:9] = self._eye3

        # --- objective ---------------------------------------------------------------------
        a_lin = (tg.base_acc + g.base_kp * (tg.base_pos - data.qpos[:3])
                 + g.base_kd * (tg.base_vel - qvel[:3]))
        omega = r_base @ qvel[3:6]
        a_ang = g.base_kp * _vee_error(self.r_ref, r_base) - g.base_kd * omega
        H = self._h_base.copy()
        grad = np.zeros(self.nx)
        grad[:3] -= g.w_task * a_lin
        grad[3:6] -= g.w_task * (r_base.T @ a_ang)
        if swing >= 0:
            press = PRESS if tg.phase[swing] == TOUCHDOWN else 0.0
            ankle_ref = tg.sole_pos + (self.foot - press) * self.normal
            a_sw = (tg.sole_acc + g.swing_kp * (ankle_ref - ankle[swing])
                    + g.swing_kd * (tg.sole_vel - ankle_vel[swing]))
            js = np.hstack([jb[swing], jl[swing]])  # (3, 9) on [base acc, swing joint acc]
            H[:9, :9] += g.w_task * (js.T @ js)
            grad[:9] -= g.w_task * (js.T @ a_sw)
        force_w = np.where(tg.phase == RELEASE, g.w_release, g.w_force)
        H[self._force_diag, self._force_diag] += np.repeat(force_w, 3)

        # --- dynamics: M_r (T x + c) + h_r = S'tau + sum J_i' f_i -------------------------
        mt = m_r @ T
        mc_h = m_r @ c + h_r
        A = mt[:6].copy()
        A[:, 9:] -= jb.transpose(2, 0, 1).reshape(6, 3 * n)  # base rows see every foot force
        b = -mc_h[:6]
        C = self._C
        lo, hi = np.full(8 * n, -INF), np.full(8 * n, INF)
        cone_rows = self._cone_rows
        hi[cone_rows[:, :4]] = (self.mu * pull)[:, None]
        lo[cone_rows[:, 4]] = -pull
        hi[cone_rows[:, 4]] = np.where(down, INF, 0.0)
        t0 = 5 * n
        C[t0:, :] = mt[6:]
        C[self._tau_rows, self._tau_cols] = -jl.transpose(0, 2, 1)  # tau_i = ... - J_leg_i' f_i
        lo[t0:], hi[t0:] = -self._tau_max - mc_h[6:], self._tau_max - mc_h[6:]

        try:
            x = self.qp.solve(H, grad, A, b, C, lo, hi)
        except InfeasibleQP:  # torque limits cannot be met: solve without, clip afterwards
            lo[t0:], hi[t0:] = -INF, INF
            x = self.qp.solve(H, grad, A, b, C, lo, hi)
        tau_ff = (C[t0:] @ x + mc_h[6:]).reshape(n, 3)

        # --- joint references and feedback -------------------------------------------------
        target = ankle.copy()
        target_vel = np.zeros((n, 3))
        if swing >= 0:
            target[swing] = ankle_ref
            target_vel[swing] = tg.sole_vel
        rel = (target - tg.base_pos) @ self.r_ref  # base frame (reference pose)
        in_leg = np.einsum("nji,nj->ni", self.rot_bl, rel - self.org_bl)
        q_ref = leg_ik(self.spec, in_leg)
        # velocity references by damped least squares (safe at a stretched leg), world frame
        jlt = jl.transpose(0, 2, 1)
        rhs = jlt @ (target_vel - tg.base_vel)[..., None]
        qd_ref = np.linalg.solve(jlt @ jl + IK_DAMPING**2 * self._eye3, rhs)[..., 0]
        command = tau_ff + self.kp * q_ref + self.kd * qd_ref
        tau = np.clip(command - self.kp * q - self.kd * qd, -self.limit, self.limit)
        return ControlOutput(command, tau, tg.magnet, tg)

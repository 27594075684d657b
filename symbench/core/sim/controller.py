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

from symbench.core.robot.specs import RobotSpec
from symbench.core.sim.gait import RELEASE, SWING, TOUCHDOWN, GaitPlan, GaitTargets
from symbench.core.sim.kinematics import leg_ik
from symbench.core.sim.layout import ModelLayout
from symbench.core.sim.model import ankle_to_sole
from symbench.core.sim.qp import INF, DenseQP, InfeasibleQP

NEXT, AFTER = np.array([1, 2, 0]), np.array([2, 0, 1])  # (a x b)_i = a_i+1 b_i+2 - a_i+2 b_i+1
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


def _cross(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """a x b over the last axis, for stacks of vectors (np.cross costs ~10 numpy calls)."""
    return a.take(NEXT, -1) * b.take(AFTER, -1) - a.take(AFTER, -1) * b.take(NEXT, -1)


def _inv3(m: np.ndarray) -> np.ndarray:
    """Inverses of a stack of 3 x 3 matrices (..., 3, 3) by the adjugate: row k of the
    cofactor matrix is row k+1 x row k+2; far fewer numpy calls than np.linalg.inv."""
    cof = _cross(m.take(NEXT, -2), m.take(AFTER, -2))
    det = (m[..., 0, :] * cof[..., 0, :]).sum(-1)
    return cof.swapaxes(-1, -2) / det[..., None, None]


class WholeBodyController:
    def __init__(
        self,
        spec: RobotSpec,
        model,
        layout: ModelLayout,
        plan: GaitPlan,
        base_rotation: np.ndarray,
        gains: ControllerGains | None = None,
    ):
        import mujoco

        self._full_m = mujoco.mj_fullM
        self.spec, self.model, self.layout, self.plan = spec, model, layout, plan
        self.gains = g = gains or ControllerGains()
        self.r_ref = base_rotation
        n = spec.n_legs
        self.n, self.nr = n, 6 + 3 * n
        self.nx = nx = 9 + 3 * n  # base acceleration (6), swing-leg joint acceleration (3), forces
        self.normal = plan.normal
        # per-leg pyramid axes: the leg's x (at the reference pose) in the surface plane
        leg_axes = np.einsum("ij,njk->nik", base_rotation, spec.leg_rotations())
        t1 = leg_axes[:, :, 0] - np.outer(leg_axes[:, :, 0] @ self.normal, self.normal)
        t1 /= np.linalg.norm(t1, axis=1, keepdims=True)
        t2 = np.cross(self.normal, t1)
        mu = spec.magnet.friction * g.friction_margin
        # rows per leg: +-t1 - mu n, +-t2 - mu n (<= mu F), then n (>= -F)
        self.cone = np.stack(
            [
                t1 - mu * self.normal,
                -t1 - mu * self.normal,
                t2 - mu * self.normal,
                -t2 - mu * self.normal,
                np.broadcast_to(self.normal, t1.shape),
            ],
            axis=1,
        )  # (n, 5, 3)
        self.mu = mu
        self.rot_bl = spec.leg_rotations()
        self.org_bl = spec.leg_origins()
        self.kp, self.kd = spec.control.kp, spec.control.kd
        self.limit = spec.torque_limits()
        self.foot = ankle_to_sole(spec)
        self._pull = spec.magnet.force * g.magnet_margin
        self.qp = DenseQP(nx, 6, 8 * n)
        self._legs = np.arange(n)
        self._liftoff: tuple[int, np.ndarray | None] = (-1, None)  # (slot, sole at release)
        # model-fixed index arrays (flat, for ndarray.take) and preallocated work arrays
        self._m_full = np.zeros((model.nv, model.nv))
        self._red_flat = (layout.reduced[:, None] * model.nv + layout.reduced[None, :]).ravel()
        self._joints = layout.joint.ravel()
        self._qpos, self._dof = layout.qpos.ravel(), layout.dof.ravel()
        # per leg, the 6 rotation axes that move its ankle (base x, y, z; coxa, femur, tibia)
        # and their levers; the Jacobian columns are their cross products
        self._axes, self._levers = np.zeros((n, 6, 3)), np.zeros((n, 6, 3))
        self._jac = np.zeros((n, 3, 9))  # [world linear base | base angular | leg joints]
        self._jac[:, :, :3] = np.eye(3)
        self._vel = np.zeros((n, 9, 1))  # the matching velocities
        self._rhs = np.zeros((n, 3, 7))  # [J_base | -stance_kd ankle velocity]
        self._T = np.zeros((self.nr, nx))  # qdd_r = T x + c
        self._T[:6, :6] = np.eye(6)
        self._T_legs = self._T[6:].reshape(n, 3, nx)
        self._c = np.zeros(self.nr)
        self._C = np.zeros((8 * n, nx))
        rows = 5 * np.arange(n)[:, None, None] + np.arange(5)[None, :, None]
        cols = 9 + 3 * np.arange(n)[:, None, None] + np.arange(3)[None, None, :]
        self._C[rows, cols] = self.cone
        tau_max = np.tile(self.limit * g.torque_margin, n)
        self._lo0 = np.concatenate([np.full(5 * n, -INF), -tau_max])
        self._hi0 = np.concatenate([np.full(5 * n, INF), tau_max])
        self._lo, self._hi = self._lo0.copy(), self._hi0.copy()
        self._cone_rows = 5 * self._legs[:, None] + np.arange(5)[None, :]
        self._friction_rows = self._cone_rows[:, :4].ravel()
        self._normal_rows = self._cone_rows[:, 4]
        k3 = np.arange(3)
        self._tau_rows = (5 * n + 3 * self._legs[:, None, None] + k3[None, :, None]) + 0 * k3
        self._tau_cols = (9 + 3 * self._legs[:, None, None] + k3[None, None, :]) + 0 * k3[:, None]
        self._force_diag = np.arange(9, nx) * (nx + 1)  # flat indices of H's force diagonal
        self._h_base = np.zeros((nx, nx))  # the constant part of the Hessian
        self._h_base[:9, :9] = g.w_qdd * np.eye(9)
        self._h_base[:6, :6] += g.w_task * np.eye(6)  # |R a| = |a|: R is orthogonal
        self._H = self._h_base.copy()
        self._grad = np.zeros(nx)
        self._eye3 = np.eye(3)
        self._ik_damping = IK_DAMPING**2 * self._eye3
        self._target_vel = np.zeros((n, 3))

    def _ankle_jacobians(self, data, ankle: np.ndarray, r_base: np.ndarray) -> np.ndarray:
        """World-frame ankle Jacobians (n, 3, 9): columns 0-5 w.r.t. the free joint
        (MuJoCo's velocity coordinates: world linear, local angular), 6-8 w.r.t. the leg's
        joints, from MuJoCo's joint axes and anchors: column = axis x (ankle - anchor)."""
        axes, levers = self._axes, self._levers
        axes[:, :3] = r_base.T  # row m: the base's axis m in the world
        axes[:, 3:] = data.xaxis.take(self._joints, 0).reshape(self.n, 3, 3)
        levers[:, :3] = (ankle - data.qpos[:3])[:, None]
        levers[:, 3:] = ankle[:, None] - data.xanchor.take(self._joints, 0).reshape(self.n, 3, 3)
        self._jac[:, :, 3:] = _cross(axes, levers).swapaxes(1, 2)
        return self._jac

    def __call__(self, data, t: float, touching: np.ndarray) -> ControlOutput:
        """Torques at time t; `touching` says which soles are close enough for the magnet."""
        g, n, nr, lay = self.gains, self.n, self.nr, self.layout
        slot = self.plan.slot_index(t)
        tg = self.plan.targets(t, self._liftoff[1] if self._liftoff[0] == slot else None)
        phase, step_leg = tg.phase, tg.step_leg
        self._full_m(self.model, data, self._m_full)
        m_r = self._m_full.take(self._red_flat).reshape(nr, nr)
        h_r = data.qfrc_bias.take(lay.reduced)
        qpos, qvel = data.qpos, data.qvel
        q = qpos.take(self._qpos).reshape(n, 3)
        qd = qvel.take(self._dof).reshape(n, 3)
        ankle = data.xpos.take(lay.ankle_body, 0)
        r_base = data.xmat[lay.base_body].reshape(3, 3)
        if step_leg >= 0 and phase[step_leg] == RELEASE:  # where the foot stands
            self._liftoff = (slot, ankle[step_leg] - self.foot * self.normal)
        jac = self._ankle_jacobians(data, ankle, r_base)
        jb, jl = jac[:, :, :6], jac[:, :, 6:]
        vel = self._vel
        vel[:, :6, 0] = qvel[:6]
        vel[:, 6:, 0] = qd
        ankle_vel = (jac @ vel)[..., 0]
        # the stepping leg is tracked while swinging and, pressing on, until it touches down
        swing = (
            step_leg
            if (
                step_leg >= 0
                and (
                    phase[step_leg] == SWING
                    or (phase[step_leg] == TOUCHDOWN and not touching[step_leg])
                )
            )
            else -1
        )

        # contact set: feet that are down (lifted only while swinging; touchdown once felt)
        down = (phase != SWING) & ((phase != TOUCHDOWN) | touching)
        pull = self._pull * tg.magnet * down

        # qdd_r = T x + c: stance legs follow the base so that their ankles do not accelerate
        # (beyond damping their residual velocity); the swing leg's joints are variables.
        # Both parts are J_leg^-1 [J_base | -kd ankle velocity], zeroed for legs that do not
        # follow (the swing leg; a lifted foot not tracked, at touchdown before contact,
        # keeps qdd = 0).
        rhs = self._rhs
        rhs[:, :, :6] = jb
        rhs[:, :, 6] = ankle_vel
        rhs[:, :, 6] *= -g.stance_kd
        inverses = _inv3(np.concatenate([jl, jl.swapaxes(1, 2) @ jl + self._ik_damping]))
        follow = inverses[:n] @ rhs
        follow *= (down & (self._legs != swing)).astype(float)[:, None, None]
        T, c = self._T, self._c
        T_legs = self._T_legs
        np.negative(follow[:, :, :6], out=T_legs[:, :, :6])
        T_legs[:, :, 6:9] = 0.0
        c[6:] = follow[:, :, 6].reshape(-1)
        if swing >= 0:
            T_legs[swing, :, 6:9] = self._eye3

        # --- objective ---------------------------------------------------------------------
        a_lin = (
            tg.base_acc
            + g.base_kp * (tg.base_pos - qpos[:3])
            + g.base_kd * (tg.base_vel - qvel[:3])
        )
        omega = r_base @ qvel[3:6]
        a_ang = g.base_kp * _vee_error(self.r_ref, r_base) - g.base_kd * omega
        H, grad = self._H, self._grad
        np.copyto(H, self._h_base)
        grad[:] = 0.0
        grad[:3] = -g.w_task * a_lin
        grad[3:6] = -g.w_task * (r_base.T @ a_ang)
        if swing >= 0:
            press = PRESS if phase[swing] == TOUCHDOWN else 0.0
            ankle_ref = tg.sole_pos + (self.foot - press) * self.normal
            a_sw = (
                tg.sole_acc
                + g.swing_kp * (ankle_ref - ankle[swing])
                + g.swing_kd * (tg.sole_vel - ankle_vel[swing])
            )
            js = jac[swing]  # (3, 9) on [base acc, swing joint acc]
            H[:9, :9] += g.w_task * (js.T @ js)
            grad[:9] -= g.w_task * (js.T @ a_sw)
        H.reshape(-1)[self._force_diag] += np.where(
            phase == RELEASE, g.w_release, g.w_force
        ).repeat(3)

        # --- dynamics: M_r (T x + c) + h_r = S'tau + sum J_i' f_i -------------------------
        mt = m_r @ T
        mc_h = m_r @ c + h_r
        A = mt[:6].copy()
        A[:, 9:] -= jb.transpose(2, 0, 1).reshape(6, 3 * n)  # base rows see every foot force
        b = -mc_h[:6]
        C, lo, hi = self._C, self._lo, self._hi
        t0 = 5 * n
        lo[:t0], hi[:t0] = self._lo0[:t0], self._hi0[:t0]
        hi[self._friction_rows] = np.repeat(self.mu * pull, 4)
        lo[self._normal_rows] = -pull
        hi[self._normal_rows] = np.where(down, INF, 0.0)
        C[t0:, :] = mt[6:]
        C[self._tau_rows, self._tau_cols] = -jl.transpose(0, 2, 1)  # tau_i = ... - J_leg_i' f_i
        np.subtract(self._lo0[t0:], mc_h[6:], out=lo[t0:])
        np.subtract(self._hi0[t0:], mc_h[6:], out=hi[t0:])

        try:
            x = self.qp.solve(H, grad, A, b, C, lo, hi)
        except InfeasibleQP:  # torque limits cannot be met: solve without, clip afterwards
            lo[t0:], hi[t0:] = -INF, INF
            x = self.qp.solve(H, grad, A, b, C, lo, hi)
        tau_ff = (C[t0:] @ x + mc_h[6:]).reshape(n, 3)

        # --- joint references and feedback -------------------------------------------------
        target = ankle.copy()
        target_vel = self._target_vel
        np.negative(tg.base_vel, out=target_vel[:])
        if swing >= 0:
            target[swing] = ankle_ref
            target_vel[swing] += tg.sole_vel
        rel = (target - tg.base_pos) @ self.r_ref  # base frame (reference pose)
        in_leg = ((rel - self.org_bl)[:, None, :] @ self.rot_bl)[:, 0]  # R_bl' (rel - o)
        q_ref = leg_ik(self.spec, in_leg)
        # velocity references by damped least squares (safe at a stretched leg), world frame
        qd_ref = (inverses[n:] @ (target_vel[:, None, :] @ jl).swapaxes(1, 2))[..., 0]
        command = tau_ff + self.kp * q_ref + self.kd * qd_ref
        tau = np.minimum(np.maximum(command - self.kp * q - self.kd * qd, -self.limit), self.limit)
        return ControlOutput(command, tau, tg.magnet, tg)

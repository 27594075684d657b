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
from symbench.core.sim.gait import RELEASE, STANCE, SWING, TOUCHDOWN, GaitPlan, GaitTargets
from symbench.core.sim.kinematics import LegIK
from symbench.core.sim.layout import ModelLayout
from symbench.core.sim.model import ankle_to_sole
from symbench.core.sim.qp import INF, DenseQP, InfeasibleQP

NEXT, AFTER = np.array([1, 2, 0]), np.array([2, 0, 1])  # (a x b)_i = a_i+1 b_i+2 - a_i+2 b_i+1
IK_DAMPING = 1e-3  # m, damping of the velocity-level leg IK
PRESS = 0.01  # m: a foot still in the air at touchdown is driven this far into the surface


@dataclass(frozen=True)
class ControllerGains:
    """Controller settings that the robot spec does not fix (chosen here)."""

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


def _vee_error(r_ref: np.ndarray, r: np.ndarray) -> list[float]:
    """Small-angle orientation error (world frame) taking R to R_ref, as Python floats."""
    e = (r_ref @ r.T).ravel().tolist()
    return [0.5 * (e[7] - e[5]), 0.5 * (e[2] - e[6]), 0.5 * (e[3] - e[1])]


def _pd(acc: list, kp: float, ref: list, pos: list, kd: float, ref_vel: list, vel: list) -> list:
    """acc + kp (ref - pos) + kd (ref_vel - vel) for 3-vectors given as lists of floats.

    Python floats do the same IEEE double operations, in the same order, as numpy does on
    the arrays (elementwise arithmetic has one correctly rounded result), at a fraction of
    the cost of seven numpy calls on 3-element arrays; the control loop runs at 1 kHz.
    """
    return [
        a + kp * (r - p) + kd * (rv - v)
        for a, r, p, rv, v in zip(acc, ref, pos, ref_vel, vel, strict=True)
    ]


def _cross(a: np.ndarray, b: np.ndarray, out: np.ndarray | None = None) -> np.ndarray:
    """a x b over the last axis, for stacks of vectors (np.cross costs ~10 numpy calls)."""
    return np.subtract(
        a.take(NEXT, -1) * b.take(AFTER, -1), a.take(AFTER, -1) * b.take(NEXT, -1), out=out
    )


def _inv3(m: np.ndarray) -> np.ndarray:
    """Inverses of a stack of 3 x 3 matrices (..., 3, 3) by the adjugate: row k of the
    cofactor matrix is row k+1 x row k+2; far fewer numpy calls than np.linalg.inv."""
    cof = _cross(m.take(NEXT, -2), m.take(AFTER, -2))
    det = (m[..., 0, :] * cof[..., 0, :]).sum(-1)
    return cof.swapaxes(-1, -2) / det[..., None, None]


def _diagonal_blocks(matrix: np.ndarray, n: int, k: int) -> np.ndarray:
    """Writable view (n, k, k) of the k x k blocks on the diagonal of `matrix` (n k, n k),
    itself a view: one strided write instead of a fancy-indexed scatter."""
    row, col = matrix.strides
    return np.lib.stride_tricks.as_strided(
        matrix, shape=(n, k, k), strides=(k * (row + col), row, col)
    )


class _StateViews:
    """numpy views of one MjData's arrays, made once: each attribute read of a MjData
    builds a new array object (about a microsecond), and a step reads a dozen."""

    def __init__(self, data, base_body: int):
        self.data = data
        self.qpos, self.qvel = data.qpos, data.qvel
        self.base_pos, self.base_linvel = self.qpos[:3], self.qvel[:3]
        self.base_angvel, self.base_qvel = self.qvel[3:6], self.qvel[:6]
        self.xpos, self.xaxis, self.xanchor = data.xpos, data.xaxis, data.xanchor
        self.qfrc_bias = data.qfrc_bias
        self.r_base = data.xmat[base_body].reshape(3, 3)


class WholeBodyController:
    """The controller of the module docstring. Per call it does the same floating-point
    operations, in the same order and on arrays of the same layout, as it always has (the
    standard datasets' content hashes depend on every bit); what does not change between
    steps (index arrays, views, masks, the QP's sparsity) is built once here."""

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
        self._neg_limit = -self.limit
        self.foot = ankle_to_sole(spec)
        self._pull = spec.magnet.force * g.magnet_margin
        self._ik = LegIK(spec)
        self.qp = DenseQP(nx, 6, 8 * n)
        self._liftoff: tuple[int, np.ndarray | None] = (-1, None)  # (slot, sole at release)
        self._views: _StateViews | None = None
        self._init_state_reads(model, layout)
        self._init_kinematics(n)
        self._init_qp(n, nx)
        self._init_masks(n)

    def _init_state_reads(self, model, layout: ModelLayout) -> None:
        """Model-fixed index arrays, shaped so that one `take` gives the array needed."""
        self._m_full = np.zeros((model.nv, model.nv))
        self._red_idx = layout.reduced[:, None] * model.nv + layout.reduced[None, :]  # (nr, nr)
        self._reduced, self._joints = layout.reduced, layout.joint
        self._qpos, self._dof = layout.qpos, layout.dof  # (n, 3) each
        self._ankle_body, self._base_body = layout.ankle_body, layout.base_body

    def _init_kinematics(self, n: int) -> None:
        """Work arrays of the ankle Jacobians, the stance legs' motion and the leg inverses."""
        # per leg, the 6 rotation axes that move its ankle (base x, y, z; coxa, femur, tibia)
        # and their levers; the Jacobian columns are their cross products
        self._axes, self._levers = np.zeros((n, 6, 3)), np.zeros((n, 6, 3))
        self._jac = np.zeros((n, 3, 9))  # [world linear base | base angular | leg joints]
        self._jac[:, :, :3] = np.eye(3)
        self._jac_rot = self._jac[:, :, 3:].swapaxes(1, 2)  # (n, 6, 3) view: cross products
        self._jb, self._jl = self._jac[:, :, :6], self._jac[:, :, 6:]
        self._vel = np.zeros((n, 9, 1))  # the matching velocities
        self._rhs = np.zeros((n, 3, 7))  # [J_base | -stance_kd ankle velocity]
        self._rhs_base, self._rhs_vel = self._rhs[:, :, :6], self._rhs[:, :, 6]
        self._eye3 = np.eye(3)
        self._ik_damping = IK_DAMPING**2 * self._eye3
        self._target_vel = np.zeros((n, 3))

    def _init_qp(self, n: int, nx: int) -> None:
        """The QP's matrices and bounds, with views of the parts rewritten at every step."""
        g = self.gains
        self._T = np.zeros((self.nr, nx))  # qdd_r = T x + c
        self._T[:6, :6] = np.eye(6)
        self._T_legs = self._T[6:].reshape(n, 3, nx)
        self._T_follow, self._T_swing = self._T_legs[:, :, :6], self._T_legs[:, :, 6:9]
        self._c = np.zeros(self.nr)
        self._c_legs = self._c[6:].reshape(n, 3)
        self._C = np.zeros((8 * n, nx))
        rows = 5 * np.arange(n)[:, None, None] + np.arange(5)[None, :, None]
        cols = 9 + 3 * np.arange(n)[:, None, None] + np.arange(3)[None, None, :]
        self._C[rows, cols] = self.cone
        t0 = 5 * n  # the torque rows start here
        self._C_tau = self._C[t0:]
        self._C_tau_blocks = _diagonal_blocks(self._C_tau[:, 9:], n, 3)  # tau_i vs f_i
        tau_max = np.tile(self.limit * g.torque_margin, n)
        self._lo0 = np.concatenate([np.full(5 * n, -INF), -tau_max])
        self._hi0 = np.concatenate([np.full(5 * n, INF), tau_max])
        self._lo, self._hi = self._lo0.copy(), self._hi0.copy()
        self._lo0_tau, self._hi0_tau = self._lo0[t0:], self._hi0[t0:]
        self._lo_tau, self._hi_tau = self._lo[t0:], self._hi[t0:]
        self._lo_normal, self._hi_normal = self._lo[4:t0:5], self._hi[4:t0:5]
        self._hi_friction = self._hi[:t0].reshape(n, 5)[:, :4]
        self._h_base = np.zeros((nx, nx))  # the constant part of the Hessian
        self._h_base[:9, :9] = g.w_qdd * np.eye(9)
        self._h_base[:6, :6] += g.w_task * np.eye(6)  # |R a| = |a|: R is orthogonal
        self._H = self._h_base.copy()
        self._H_swing = self._H[:9, :9]
        self._H_force_diag = self._H.reshape(-1)[9 * (nx + 1) :: nx + 1]  # view
        self._grad = np.zeros(nx)
        self._grad_lin, self._grad_ang, self._grad_swing = (
            self._grad[:3],
            self._grad[3:6],
            self._grad[:9],
        )

    def _init_masks(self, n: int) -> None:
        """Everything that depends only on which leg swings or releases, indexed by that leg
        (index -1, the last entry: none)."""
        g = self.gains
        legs = np.arange(n)
        self._down, self._follow_mask, self._normal_cap, self._force_weight = [], [], [], []
        for leg in [*range(n), -1]:
            down = legs != leg  # contact set: every foot but a lifted one
            down.flags.writeable = False
            self._down.append(down)
            self._follow_mask.append(down.astype(float)[:, None, None])
            self._normal_cap.append(np.where(down, INF, 0.0))
            weights = np.where(legs == leg, g.w_release, g.w_force).repeat(3)
            self._force_weight.append(weights)

    def _state_views(self, data) -> _StateViews:
        """The views of `data`, made on the first call with it."""
        views = self._views
        if views is None or views.data is not data:
            views = self._views = _StateViews(data, self._base_body)
        return views

    def _ankle_jacobians(self, v: _StateViews, ankle: np.ndarray) -> np.ndarray:
        """World-frame ankle Jacobians (n, 3, 9): columns 0-5 w.r.t. the free joint
        (MuJoCo's velocity coordinates: world linear, local angular), 6-8 w.r.t. the leg's
        joints, from MuJoCo's joint axes and anchors: column = axis x (ankle - anchor)."""
        axes, levers = self._axes, self._levers
        axes[:, :3] = v.r_base.T  # row m: the base's axis m in the world
        axes[:, 3:] = v.xaxis.take(self._joints, 0)
        levers[:, :3] = (ankle - v.base_pos)[:, None]
        np.subtract(ankle[:, None], v.xanchor.take(self._joints, 0), out=levers[:, 3:])
        _cross(axes, levers, out=self._jac_rot)
        return self._jac

    def _leg_inverses(self) -> np.ndarray:
        """(2n, 3, 3): J_leg^-1, then (J_leg' J_leg + damping)^-1 for the damped IK."""
        jl = self._jl
        return _inv3(np.concatenate([jl, jl.swapaxes(1, 2) @ jl + self._ik_damping]))

    def __call__(self, data, t: float, touching: np.ndarray) -> ControlOutput:
        """Torques at time t; `touching` says which soles are close enough for the magnet."""
        g, n = self.gains, self.n
        v = self._state_views(data)
        slot = self.plan.slot_index(t)
        tg = self.plan.targets(t, self._liftoff[1] if self._liftoff[0] == slot else None)
        step_leg = tg.step_leg
        step_phase = tg.phase[step_leg] if step_leg >= 0 else STANCE
        self._full_m(self.model, data, self._m_full)
        m_r = self._m_full.take(self._red_idx)
        h_r = v.qfrc_bias.take(self._reduced)
        q, qd = v.qpos.take(self._qpos), v.qvel.take(self._dof)
        ankle = v.xpos.take(self._ankle_body, 0)
        r_base = v.r_base
        if step_phase == RELEASE:  # where the foot stands
            sole = ankle[step_leg] - self.foot * self.normal
            sole.flags.writeable = False  # the plan caches the swing from it by identity
            self._liftoff = (slot, sole)
        jac = self._ankle_jacobians(v, ankle)
        jb, jl = self._jb, self._jl
        vel = self._vel
        vel[:, :6, 0] = v.base_qvel
        vel[:, 6:, 0] = qd
        ankle_vel = (jac @ vel)[..., 0]
        # the stepping leg is tracked while swinging and, pressing on, until it touches down
        lifted = step_phase == SWING or (step_phase == TOUCHDOWN and not touching[step_leg])
        swing = step_leg if lifted else -1

        # contact set: feet that are down (lifted only while swinging; touchdown once felt)
        down = self._down[swing]
        pull = self._pull * tg.magnet * down

        # qdd_r = T x + c: stance legs follow the base so that their ankles do not accelerate
        # (beyond damping their residual velocity); the swing leg's joints are variables.
        # Both parts are J_leg^-1 [J_base | -kd ankle velocity], zeroed for legs that do not
        # follow (the swing leg; a lifted foot not tracked, at touchdown before contact,
        # keeps qdd = 0).
        self._rhs_base[...] = jb
        np.multiply(ankle_vel, -g.stance_kd, out=self._rhs_vel)
        inverses = self._leg_inverses()
        follow = inverses[:n] @ self._rhs
        follow *= self._follow_mask[swing]
        T, c = self._T, self._c
        np.negative(follow[:, :, :6], out=self._T_follow)
        self._T_swing[...] = 0.0
        self._c_legs[...] = follow[:, :, 6]
        if swing >= 0:
            self._T_swing[swing] = self._eye3

        # --- objective ---------------------------------------------------------------------
        # 3-vector arithmetic on Python floats (see _pd); matrix products stay numpy's
        a_lin = _pd(
            tg.base_acc.tolist(),
            g.base_kp,
            tg.base_pos.tolist(),
            v.base_pos.tolist(),
            g.base_kd,
            tg.base_vel.tolist(),
            v.base_linvel.tolist(),
        )
        omega = (r_base @ v.base_angvel).tolist()
        vee = _vee_error(self.r_ref, r_base)
        a_ang = [g.base_kp * e - g.base_kd * w for e, w in zip(vee, omega, strict=True)]
        H, grad = self._H, self._grad
        np.copyto(H, self._h_base)
        grad[:] = 0.0
        w_neg = -g.w_task
        self._grad_lin[:] = [w_neg * a for a in a_lin]
        np.multiply(w_neg, r_base.T @ np.array(a_ang), out=self._grad_ang)
        if swing >= 0:
            reach = self.foot - (PRESS if step_phase == TOUCHDOWN else 0.0)
            ankle_ref = tg.sole_pos + reach * self.normal
            a_sw = _pd(
                tg.sole_acc.tolist(),
                g.swing_kp,
                ankle_ref.tolist(),
                ankle[swing].tolist(),
                g.swing_kd,
                tg.sole_vel.tolist(),
                ankle_vel[swing].tolist(),
            )
            js = jac[swing]  # (3, 9) on [base acc, swing joint acc]
            self._H_swing += g.w_task * (js.T @ js)
            self._grad_swing -= g.w_task * (js.T @ np.array(a_sw))
        self._H_force_diag += self._force_weight[step_leg if step_phase == RELEASE else -1]

        # --- dynamics: M_r (T x + c) + h_r = S'tau + sum J_i' f_i -------------------------
        mt = m_r @ T
        mc_h = m_r @ c + h_r
        A = mt[:6]  # a view: C takes the other rows
        A[:, 9:] -= jb.transpose(2, 0, 1).reshape(6, 3 * n)  # base rows see every foot force
        b = -mc_h[:6]
        C, lo, hi = self._C, self._lo, self._hi
        np.multiply(self.mu, pull[:, None], out=self._hi_friction)
        np.negative(pull, out=self._lo_normal)
        self._hi_normal[...] = self._normal_cap[swing]
        self._C_tau[...] = mt[6:]
        np.negative(jl.transpose(0, 2, 1), out=self._C_tau_blocks)  # tau_i = ... - J_leg_i' f_i
        mc_h_tau = mc_h[6:]
        np.subtract(self._lo0_tau, mc_h_tau, out=self._lo_tau)
        np.subtract(self._hi0_tau, mc_h_tau, out=self._hi_tau)

        try:
            x = self.qp.solve(H, grad, A, b, C, lo, hi)
        except InfeasibleQP:  # torque limits cannot be met: solve without, clip afterwards
            self._lo_tau[...], self._hi_tau[...] = -INF, INF
            x = self.qp.solve(H, grad, A, b, C, lo, hi)
        tau_ff = (self._C_tau @ x + mc_h_tau).reshape(n, 3)

        # --- joint references and feedback -------------------------------------------------
        target = ankle  # not read below: its rows become the targets
        target_vel = self._target_vel
        np.negative(tg.base_vel, out=target_vel)
        if swing >= 0:
            target[swing] = ankle_ref
            target_vel[swing] += tg.sole_vel
        rel = (target - tg.base_pos) @ self.r_ref  # base frame (reference pose)
        in_leg = ((rel - self.org_bl)[:, None, :] @ self.rot_bl)[:, 0]  # R_bl' (rel - o)
        q_ref = self._ik(in_leg)
        # velocity references by damped least squares (safe at a stretched leg), world frame
        qd_ref = (inverses[n:] @ (target_vel[:, None, :] @ jl).swapaxes(1, 2))[..., 0]
        command = tau_ff + self.kp * q_ref + self.kd * qd_ref
        tau = np.minimum(
            np.maximum(command - self.kp * q - self.kd * qd, self._neg_limit), self.limit
        )
        return ControlOutput(command, tau, tg.magnet, tg)

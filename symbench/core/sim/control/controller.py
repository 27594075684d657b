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
   the feedback runs inside MuJoCo's actuator (symbench.core.sim.scene.mjcf) so that the
   implicit integrator keeps it stable, the controller sends u = tau_ff + Kp q_ref + Kd qd_ref.
The friction pyramid's tangent axes follow each leg's frame, so nothing depends on leg
numbering beyond relabelling: the whole loop is equivariant under the robot's rotations.
The arithmetic of steps 1-3 is compiled (`control.kernel`); this class holds what does not
change between steps and asks the gait plan and the QP solver.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import NamedTuple

import numpy as np

from symbench.core.robot.specs import RobotSpec
from symbench.core.sim.control import kernel
from symbench.core.sim.control.qp import DenseQP
from symbench.core.sim.gait.plan import GaitPlan, GaitTargets
from symbench.core.sim.scene.layout import ModelLayout
from symbench.core.sim.scene.mjcf import ankle_to_sole

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


class ControlOutput(NamedTuple):
    command: np.ndarray  # (n, 3) servo input u = tau_ff + Kp q_ref + Kd qd_ref
    tau: np.ndarray  # (n, 3) torque the servo applies at this state: clip(u - Kp q - Kd qd)
    magnet: np.ndarray  # (n,)
    targets: GaitTargets


class WholeBodyController:
    """The controller of the module docstring for one climb: its constants (gains, the
    friction pyramids, index arrays, the QP's fixed rows) and work arrays, built once and
    handed to the compiled `control_kernel.control_step` by `kernel_args`."""

    def __init__(
        self,
        spec: RobotSpec,
        model,
        layout: ModelLayout,
        plan: GaitPlan,
        base_rotation: np.ndarray,
        gains: ControllerGains | None = None,
    ):
        g = gains or ControllerGains()
        self.model = model
        n = spec.n_legs
        nx = 9 + 3 * n  # base acceleration (6), swing-leg joint acceleration (3), forces
        n_rows = 6 + 8 * n  # floating-base equations, 5 pyramid rows and 3 torque rows a leg
        normal = np.ascontiguousarray(plan.normal, dtype=float)
        gain_vector = _gain_vector(spec, g)
        h_base = np.zeros((nx, nx))  # the constant part of the Hessian
        h_base[:9, :9] = g.w_qdd * np.eye(9)
        h_base[:6, :6] += g.w_task * np.eye(6)  # |R a| = |a|: R is orthogonal
        hess, grad = np.zeros((nx, nx)), np.zeros(nx)
        cons, lower, upper = np.zeros((n_rows, nx)), np.zeros(n_rows), np.zeros(n_rows)
        cons[6 : 6 + 5 * n] = _pyramids(spec, base_rotation, normal, gain_vector[kernel.MU], nx)
        self.qp = DenseQP(hess, grad, cons, lower, upper, n_eq=6, dense=9)
        self._m_full = np.zeros((model.nv, model.nv))
        self._layout = (
            *(
                np.ascontiguousarray(a, dtype=np.int64)
                for a in (layout.reduced, layout.joint, layout.qpos, layout.dof, layout.ankle_body)
            ),
            int(layout.base_body),
        )
        self._plan = plan.kernel_args
        control = spec.control
        self._fixed = (
            gain_vector,
            np.ascontiguousarray(base_rotation, dtype=float),  # the base orientation reference
            h_base,
            spec.torque_limits() * g.torque_margin,
            np.ascontiguousarray(spec.leg_rotations(), dtype=float),
            np.ascontiguousarray(spec.leg_origins(), dtype=float),
            np.array([spec.leg.lengths[k] for k in ("coxa", "femur", "tibia")]),
            np.array([control.kp, control.kd, control.torque_limit]),
        )
        self._liftoff = np.array([-2.0, 0.0, 0.0, 0.0])  # [slot, sole at release]; -2: none
        # the QP's arrays, then what the servo command reads: ankle Jacobians (n, 3, 9),
        # per leg [ankle, ankle velocity, q, qd], damped IK inverses, M c + h of the torque
        # rows, the swing ankle's target
        self._work = (
            hess,
            grad,
            cons,
            lower,
            upper,
            np.zeros((n, 3, 9)),
            np.zeros((n, 4, 3)),
            np.zeros((n, 3, 3)),
            np.zeros(3 * n),
            np.zeros(3),
        )

    def kernel_args(self, data) -> tuple:
        """The arguments of `control_kernel.control_step` after (t, touching), bound to
        `data` (the model's MjData): pointers, state views, index arrays, the plan, the
        fixed settings, the liftoff memory, the work arrays and the QP."""
        state = (
            self._m_full,
            data.qfrc_bias,
            data.qpos,
            data.qvel,
            data.xpos,
            data.xaxis,
            data.xanchor,
            data.xmat,
        )
        return (
            self.model._address,
            data._address,
            state,
            self._layout,
            self._plan,
            self._fixed,
            self._liftoff,
            self._work,
            self.qp.kernel_args,
        )


def _gain_vector(spec: RobotSpec, g: ControllerGains) -> np.ndarray:
    """The kernel's float settings, at the indices `control.kernel` names."""
    values = np.zeros(kernel.N_GAINS)
    values[kernel.BASE_KP], values[kernel.BASE_KD] = g.base_kp, g.base_kd
    values[kernel.SWING_KP], values[kernel.SWING_KD] = g.swing_kp, g.swing_kd
    values[kernel.STANCE_KD], values[kernel.W_TASK] = g.stance_kd, g.w_task
    values[kernel.W_FORCE], values[kernel.W_RELEASE] = g.w_force, g.w_release
    values[kernel.IK_DAMPING_SQ] = IK_DAMPING**2
    values[kernel.FOOT], values[kernel.PRESS] = ankle_to_sole(spec), PRESS
    values[kernel.MU] = spec.magnet.friction * g.friction_margin
    values[kernel.PULL] = spec.magnet.force * g.magnet_margin
    return values


def _pyramids(
    spec: RobotSpec, base_rotation: np.ndarray, normal: np.ndarray, mu: float, nx: int
) -> np.ndarray:
    """The 5 QP rows per foot: +-t1 - mu n, +-t2 - mu n (<= mu F), then n (>= -F); the
    tangent axes are the leg's x (at the reference pose) in the surface plane."""
    n = spec.n_legs
    leg_axes = np.einsum("ij,njk->nik", base_rotation, spec.leg_rotations())
    t1 = leg_axes[:, :, 0] - np.outer(leg_axes[:, :, 0] @ normal, normal)
    t1 /= np.linalg.norm(t1, axis=1, keepdims=True)
    t2 = np.cross(normal, t1)
    cone = np.stack(
        [t1 - mu * normal, -t1 - mu * normal, t2 - mu * normal, -t2 - mu * normal], axis=1
    )
    rows = np.zeros((5 * n, nx))
    for i in range(n):
        rows[5 * i : 5 * i + 4, 9 + 3 * i : 12 + 3 * i] = cone[i]
        rows[5 * i + 4, 9 + 3 * i : 12 + 3 * i] = normal
    return rows

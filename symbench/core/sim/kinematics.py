"""Closed-form leg kinematics in the leg frame, vectorised over legs.

The ankle (the end of the tibia, centre of the passive gimbal) is the point the joints
control; with the gimbal free, the foot's contact force passes through it. Leg frame: x
along the coxa's zero direction, z up; femur and tibia pitch about -y (positive lifts).
"""

from __future__ import annotations

import numpy as np

from symbench.core.robot.specs import RobotSpec


def leg_fk(spec: RobotSpec, q: np.ndarray) -> np.ndarray:
    """Ankle positions (..., 3) in the leg frames for joint angles q (..., 3)."""
    lc, lf, lt = (spec.leg.lengths[k] for k in ("coxa", "femur", "tibia"))
    q0, q1, q2 = q[..., 0], q[..., 1], q[..., 2]
    reach = lc + lf * np.cos(q1) + lt * np.cos(q1 + q2)
    height = lf * np.sin(q1) + lt * np.sin(q1 + q2)
    return np.stack([reach * np.cos(q0), reach * np.sin(q0), height], axis=-1)


def leg_ik(spec: RobotSpec, ankle: np.ndarray) -> np.ndarray:
    """Joint angles (..., 3) putting the ankle at `ankle` (..., 3), knee-up branch.

    A target out of reach is clipped to the nearest reachable knee angle (straight or
    folded leg), so the controller never stops mid-step; the tracking error shows it.
    """
    return LegIK(spec)(ankle)


class LegIK:
    """`leg_ik` for one spec, its length constants looked up once: the controller calls it
    at every control step, where the lookups cost as much as the arithmetic. The constants
    are the same Python numbers the expressions used to build each call, so the results are
    bit for bit those of `leg_ik`."""

    def __init__(self, spec: RobotSpec):
        self.lc, self.lf, self.lt = (spec.leg.lengths[k] for k in ("coxa", "femur", "tibia"))
        lf, lt = self.lf, self.lt
        self.sum_sq = lf * lf + lt * lt
        self.twice_product = 2 * lf * lt

    def __call__(self, ankle: np.ndarray) -> np.ndarray:
        lc, lf, lt = self.lc, self.lf, self.lt
        x, y, height = ankle[..., 0], ankle[..., 1], ankle[..., 2]
        q = np.empty(ankle.shape)  # filled in place: this runs at every control step
        q[..., 0] = np.arctan2(y, x)
        reach = np.hypot(x, y) - lc
        cos_knee = (reach * reach + height * height - self.sum_sq) / self.twice_product
        q2 = q[..., 2]
        np.negative(np.arccos(np.minimum(np.maximum(cos_knee, -1.0), 1.0)), out=q2)  # bends down
        q[..., 1] = np.arctan2(height, reach) - np.arctan2(lt * np.sin(q2), lf + lt * np.cos(q2))
        return q

"""Closed-form leg kinematics in the leg frame, vectorised over legs.

The ankle (the end of the tibia, centre of the passive gimbal) is the point the joints
control; with the gimbal free, the foot's contact force passes through it. Leg frame: x
along the coxa's zero direction, z up; femur and tibia pitch about -y (positive lifts).
"""

from __future__ import annotations

import numpy as np
from numba import njit

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
    lengths = np.array([spec.leg.lengths[k] for k in ("coxa", "femur", "tibia")])
    flat = np.ascontiguousarray(ankle, dtype=float).reshape(-1, 3)
    q = np.empty(flat.shape)
    for row, out in zip(flat, q, strict=True):
        leg_ik_into(row[0], row[1], row[2], lengths, out)
    return q.reshape(np.shape(ankle))


@njit(cache=True)
def leg_ik_into(x, y, height, lengths, q):
    """`leg_ik` of one ankle position (x, y, height) into q (3,); lengths = (coxa, femur,
    tibia). Compiled: the controller calls it for every leg at every control step."""
    lc, lf, lt = lengths[0], lengths[1], lengths[2]
    q[0] = np.arctan2(y, x)
    reach = np.hypot(x, y) - lc
    cos_knee = (reach * reach + height * height - (lf * lf + lt * lt)) / (2 * lf * lt)
    q[2] = -np.arccos(min(max(cos_knee, -1.0), 1.0))  # the knee bends down
    q[1] = np.arctan2(height, reach) - np.arctan2(lt * np.sin(q[2]), lf + lt * np.cos(q[2]))

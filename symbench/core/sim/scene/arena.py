"""The climbing surface: a plane through the world origin with any inclination and heading.

Surface frame S: z_s is the surface normal (pointing away from the material, towards the
robot), x_s points up the slope (for a floor or ceiling, along the heading). Gravity is
always (0, 0, -9.81); the scene heading rotates the plane and the robot's start about
world z, so it changes only world-frame quantities.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from symbench.core.common.errors import SymbenchError


def rot_z(angle: float) -> np.ndarray:
    c, s = np.cos(angle), np.sin(angle)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def rot_y(angle: float) -> np.ndarray:
    c, s = np.cos(angle), np.sin(angle)
    return np.array([[c, 0.0, s], [0.0, 1.0, 0.0], [-s, 0.0, c]])


def mat_to_quat(rot: np.ndarray) -> np.ndarray:
    """(w, x, y, z) of a rotation matrix, through MuJoCo for consistency with the model."""
    import mujoco

    quat = np.zeros(4)
    mujoco.mju_mat2Quat(quat, np.ascontiguousarray(rot).reshape(9))
    return quat


@dataclass(frozen=True)
class Arena:
    inclination_deg: float = 0.0
    heading_deg: float = 0.0

    def __post_init__(self) -> None:
        if not 0.0 <= self.inclination_deg <= 180.0:
            raise SymbenchError(f"arena: inclination_deg {self.inclination_deg} is outside 0..180")

    @property
    def rotation(self) -> np.ndarray:
        """R_ws: columns are the surface axes (x up-slope, y, z normal) in the world frame."""
        return rot_z(np.radians(self.heading_deg)) @ rot_y(-np.radians(self.inclination_deg))

    @property
    def normal(self) -> np.ndarray:
        return self.rotation[:, 2]

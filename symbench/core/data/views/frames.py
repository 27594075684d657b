"""Rotations and leg frames, vectorised over samples, for the raw-to-view transforms."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from symbench.core.common.errors import SymbenchError

GRAVITY_WORLD = np.array([0.0, 0.0, -9.81])


def quat_to_matrix(quat: np.ndarray) -> np.ndarray:
    """(..., 4) unit quaternions (w, x, y, z) -> (..., 3, 3) rotation matrices."""
    q = quat / np.linalg.norm(quat, axis=-1, keepdims=True)
    w, x, y, z = np.moveaxis(q, -1, 0)
    return np.stack(
        [
            np.stack([1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)], -1),
            np.stack([2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)], -1),
            np.stack([2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)], -1),
        ],
        -2,
    )


def quat_multiply(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Hamilton product a * b of (..., 4) quaternions (w, x, y, z): rotation b, then a."""
    aw, ax, ay, az = np.moveaxis(a, -1, 0)
    bw, bx, by, bz = np.moveaxis(b, -1, 0)
    return np.stack(
        [
            aw * bw - ax * bx - ay * by - az * bz,
            aw * bx + ax * bw + ay * bz - az * by,
            aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw,
        ],
        -1,
    )


def yaw_quat(angle: float) -> np.ndarray:
    """Quaternion of a rotation by `angle` (rad) about z."""
    return np.array([np.cos(angle / 2), 0.0, 0.0, np.sin(angle / 2)])


def yaw_matrix(angle: float) -> np.ndarray:
    c, s = np.cos(angle), np.sin(angle)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


@dataclass(frozen=True)
class LegFrames:
    """Where each leg frame sits on the base: what the views need from a robot spec."""

    rotations: np.ndarray  # (n_legs, 3, 3) R_b_li: columns are leg axes in the base frame
    origins: np.ndarray  # (n_legs, 3) leg-frame origins in the base frame

    def __post_init__(self) -> None:
        n = len(self.rotations)
        if self.rotations.shape != (n, 3, 3) or self.origins.shape != (n, 3):
            raise SymbenchError(
                f"leg frames: rotations {self.rotations.shape} and origins "
                f"{self.origins.shape} do not describe the same legs"
            )

    @property
    def n_legs(self) -> int:
        return len(self.rotations)

    @classmethod
    def from_spec(cls, spec) -> LegFrames:
        """From a `symbench.core.robot.specs.RobotSpec` (anything with leg_rotations and
        leg_origins)."""
        return cls(np.asarray(spec.leg_rotations(), float), np.asarray(spec.leg_origins(), float))

    def base_origin_in_legs(self) -> np.ndarray:
        """(n_legs, 3) p_i: the base origin expressed in each leg frame."""
        return -np.einsum("lji,lj->li", self.rotations, self.origins)

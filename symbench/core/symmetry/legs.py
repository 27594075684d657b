"""Whether a robot's leg geometry has the symmetry its spec declares.

A group element carries leg i to leg perm[i]. It is a symmetry of the geometry when one
base rotation about z (times the leg mirror for reflections) carries every leg frame onto
its image; that rotation is what the element does to the base (`base_map`).
"""

from __future__ import annotations

import numpy as np

from symbench.core.common.errors import SymbenchError
from symbench.core.symmetry.groups import GroupElement, LegGroup

MIRROR_Y = np.diag([1.0, -1.0, 1.0])  # mirror in the x-z plane (a leg's, or the world's)


def base_map(
    rotations: np.ndarray, origins: np.ndarray, g: GroupElement, tol: float = 1e-9
) -> np.ndarray:
    """G_b (3, 3) with G_b R_b_li = R_b_l(perm i) S and G_b o_i = o_(perm i), S the leg mirror."""
    n = len(rotations)
    if g.n_legs != n:
        raise SymbenchError(f"{g!r} acts on {g.n_legs} legs, the robot has {n}")
    s = MIRROR_Y if g.reflect else np.eye(3)
    perm = list(g.perm)
    gb = rotations[perm[0]] @ s @ rotations[0].T
    frames_ok = np.allclose(gb @ rotations, rotations[perm] @ s, atol=tol)
    origins_ok = np.allclose(origins @ gb.T, origins[perm], atol=tol)
    if not (frames_ok and origins_ok and np.allclose(gb[:, 2], [0, 0, 1], atol=tol)):
        raise SymbenchError(
            f"the robot's leg frames are not symmetric under {g!r}: "
            "check the mounts and coxa yaws of its robot.toml"
        )
    return gb


def check_geometry(
    rotations: np.ndarray, origins: np.ndarray, group: LegGroup, source: str, tol: float = 1e-6
) -> None:
    """Refuse a spec whose legs do not have the declared symmetry (generators suffice)."""
    for g in group.generators:
        try:
            base_map(rotations, origins, g, tol)
        except SymbenchError as exc:
            raise SymbenchError(f"{source}: declares group {group.name}, but {exc}") from None

"""Whether a robot's leg geometry has the symmetry its spec declares.

A group element carries leg i to leg perm[i]. It is a symmetry of the geometry when one
base rotation about z (times the leg mirror for reflections) carries every leg frame onto
its image; that rotation is what the element does to the base (`base_map`).

A spec declares the group its models and splits use; the geometry may have more. Every
robot built from identical legs on a symmetric base also has mirror planes (magneto two,
hexa six, nona nine), which `geometry_group` finds from the leg frames and the base's
inertia and shape alone, so that `symbench sim check` can verify them in physics whether
or not the spec declares them.
"""

from __future__ import annotations

import numpy as np

from symbench.core.common.errors import SymbenchError
from symbench.core.symmetry.groups import GroupElement, LegGroup, dihedral, mirror

MIRROR_Y = np.diag([1.0, -1.0, 1.0])  # mirror in the x-z plane (a leg's, or the world's)
# A leg's mirror in its own x-z plane on (coxa, femur, tibia) angles, velocities and torques:
# the coxa turns about z (in the plane) and flips; femur and tibia turn about y (normal to
# it) and keep their sign.
JOINT_MIRROR_SIGNS = (-1.0, 1.0, 1.0)


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
    rotations: np.ndarray,
    origins: np.ndarray,
    group: LegGroup,
    source: str,
    base_tensors: tuple[np.ndarray, ...] = (),
    tol: float = 1e-6,
) -> None:
    """Refuse a spec whose legs, or base (its inertia and shape as 3x3 `base_tensors`), do
    not have the declared symmetry (generators suffice)."""
    for g in group.generators:
        try:
            gb = base_map(rotations, origins, g, tol)
        except SymbenchError as exc:
            raise SymbenchError(f"{source}: declares group {group.name}, but {exc}") from None
        if not _keeps(gb, base_tensors, tol):
            raise SymbenchError(
                f"{source}: declares group {group.name}, but the base's inertia or shape is "
                f"not symmetric under {g!r}: check base.inertia and base.semi_axes"
            )


def geometry_group(
    rotations: np.ndarray,
    origins: np.ndarray,
    declared: LegGroup,
    base_tensors: tuple[np.ndarray, ...] = (),
    tol: float = 1e-6,
) -> LegGroup:
    """The declared group's rotations with a mirror, when the geometry has one: the leg
    frames and mounts (`base_map`) and the base's `base_tensors` all map onto themselves.
    One mirror suffices, the rotations give the others. A group of two rotations and its
    mirrors is the Klein four-group (named K4), otherwise dihedral."""
    if declared.has_reflections:
        return declared
    n = declared.n_legs
    for offset in range(n):
        g = mirror(n, offset)
        try:
            gb = base_map(rotations, origins, g, tol)
        except SymbenchError:
            continue
        if _keeps(gb, base_tensors, tol):
            rotations_order = declared.rotation_order
            name = "K4" if rotations_order == 2 else f"D{rotations_order}"
            return dihedral(n, n // rotations_order, offset, name)
    return declared


def _keeps(gb: np.ndarray, tensors: tuple[np.ndarray, ...], tol: float) -> bool:
    return all(np.allclose(gb @ t @ gb.T, t, atol=tol * max(1.0, np.abs(t).max())) for t in tensors)

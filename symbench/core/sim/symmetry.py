"""The symmetry of the whole loop, measured: a run and its twin under a group element.

Rotating the base by the group's angle (360 k / n degrees) while relabelling legs by k puts
every body of the robot exactly where it was, so physics, planner and controller must
reproduce the original run leg for leg; the twin steps in the body direction rotated back
by the same angle (the same direction in the world) with the leg order relabelled.

A mirror twin mirrors the whole scene in the plane through the surface normal and the slope
line (surface and gravity stay as they are): the robot's mirror image is the robot again,
legs relabelled and each leg mirrored (coxa angles, velocities and torques flip sign); the
twin's base yaw, step direction, swing order and start perturbation are the mirrored ones
(`Climb.reflected`).

`check_generators` does this for every generator of the robot's geometry group, the declared
group and the mirrors its geometry also has (what `symbench sim check` reports): a group is
verified when its generators are, since every element is a product of them.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from symbench.core.sim.climb.rollout import Rollout, run_climb
from symbench.core.sim.raw import FLAG_COLUMNS, JOINT_COLUMNS, WORLD_VECTORS
from symbench.core.sim.scene.setup import Climb
from symbench.core.symmetry.groups import GroupElement
from symbench.core.symmetry.legs import JOINT_MIRROR_SIGNS, MIRROR_Y, base_map

# The largest error a generator may show, relative: per column, the largest difference
# between twin and run divided by the column's largest magnitude in the run (accelerations in
# stiff magnetic contacts reach 1e3 rad/s^2, positions a few tenths of a metre). Twins of the
# built-in robots agree to 1e-11 over a second and 1e-7 over ten (rounding differences grow
# through contact switches); a broken symmetry (a mislabelled leg, an asymmetric part) shows
# 1e-3 and more.
TOLERANCE = 1e-5


def twin_climb(climb: Climb, g: GroupElement) -> Climb:
    """The climb's twin under `g`: turned by its rotation, or mirrored, legs relabelled so
    that twin leg j plays the part of leg g.perm[j]."""
    if g.reflect:
        return climb.reflected(g)
    return climb.turned(g.perm[0] // climb.spec.symmetry_shift)


def expected_twin(run: Rollout, climb: Climb, g: GroupElement) -> dict[str, np.ndarray]:
    """What the twin under `g` must record, computed from the run of `climb`: leg j is leg
    g.perm[j] (mirrored by a reflection), world vectors mirrored with the scene, the base
    orientation R_wb carried to W R_wb G_b (W the scene's mirror or the identity, G_b the
    element's base map)."""
    spec, arrays = climb.spec, run.arrays
    gb = base_map(spec.leg_rotations(), spec.leg_origins(), g)
    surface = climb.arena.rotation
    world = surface @ MIRROR_Y @ surface.T if g.reflect else np.eye(3)
    signs = np.asarray(JOINT_MIRROR_SIGNS) if g.reflect else np.ones(3)
    legs = np.asarray(g.perm)
    out = {c: arrays[c][:, legs] * signs for c in JOINT_COLUMNS}
    out |= {c: arrays[c][:, legs] for c in FLAG_COLUMNS}
    out |= {c: arrays[c] @ world.T for c in WORLD_VECTORS}
    out["base_angvel"] = np.linalg.det(world) * (arrays["base_angvel"] @ world.T)
    out["base_rotation"] = world @ base_rotations(arrays["base_quat"]) @ gb
    return out


def base_rotations(quats: np.ndarray) -> np.ndarray:
    """(T, 3, 3) R_wb of (T, 4) MuJoCo quaternions: compared as matrices, free of the sign."""
    import mujoco

    out = np.empty((len(quats), 9))
    for row, quat in zip(out, np.asarray(quats, np.float64)):
        mujoco.mju_quat2Mat(row, quat)
    return out.reshape(-1, 3, 3)


def twin_errors(run: Rollout, twin: Rollout, climb: Climb, g: GroupElement) -> dict[str, float]:
    """Per column, the largest difference between the twin and what it must record, relative
    to the column's largest magnitude in the run, over the rows both have."""
    expected = expected_twin(run, climb, g)
    actual = {c: twin.arrays[c] for c in expected if c != "base_rotation"}
    actual["base_rotation"] = base_rotations(twin.arrays["base_quat"])
    rows = min(len(run.arrays["t"]), len(twin.arrays["t"]))
    return {
        c: float(np.abs(actual[c][:rows] - want[:rows]).max())
        / max(float(np.abs(want[:rows]).max()), 1e-12)
        for c, want in expected.items()
    }


@dataclass(frozen=True)
class GeneratorCheck:
    """One generator of the robot's geometry group, simulated: `error` is the largest
    relative column error; `declared` says whether the spec's group contains it."""

    generator: str
    error: float
    worst_column: str
    declared: bool = True
    columns: dict[str, float] = field(default_factory=dict)

    @property
    def ok(self) -> bool:
        return self.error <= TOLERANCE

    def to_dict(self) -> dict:
        return {
            "generator": self.generator,
            "declared": self.declared,
            "error": self.error,
            "worst_column": self.worst_column,
            "within_tolerance": self.ok,
            "columns": self.columns,
        }


def check_element(
    climb: Climb,
    g: GroupElement,
    seconds: float,
    original: Rollout | None = None,
    control_period: float | None = None,
) -> GeneratorCheck:
    """`climb`'s twin under `g`, simulated and compared with `original` (a run of `climb`
    at least `seconds` long; simulated when not given)."""
    if original is None:
        original = run_climb(climb, seconds, control_period=control_period)
    twin = run_climb(twin_climb(climb, g), seconds, control_period=control_period)
    errors = twin_errors(original, twin, climb, g)
    worst = max(errors, key=lambda c: errors[c])
    return GeneratorCheck(g.name, errors[worst], worst, g in climb.spec.group, errors)


def check_generators(
    climb: Climb,
    seconds: float,
    original: Rollout | None = None,
    control_period: float | None = None,
) -> list[GeneratorCheck]:
    """Each generator of `climb`'s robot geometry group (declared rotations and mirrors),
    checked by `check_element` over `seconds`."""
    if original is None:
        original = run_climb(climb, seconds, control_period=control_period)
    return [
        check_element(climb, g, seconds, original, control_period)
        for g in climb.spec.geometry_group.generators
    ]

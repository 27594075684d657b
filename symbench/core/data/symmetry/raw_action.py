"""A robot's symmetry acting on raw states, so that `view(g . raw) == g . view(raw)` is testable.

A rotation element relabels the legs (leg i becomes leg perm[i]) and turns the base about its
own z by minus the element's angle, so every leg lands where its predecessor was: the world
sees the same robot, described with shifted labels. A reflection relabels the legs, mirrors
each leg (coxa angles flip) and mirrors the scene in the world x-z plane, which keeps gravity.
The element's base-frame map comes from the leg frames, so a robot that is not symmetric
under the element is refused instead of silently giving wrong numbers.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np

from symbench.core.common.errors import SymbenchError
from symbench.core.data.views.frames import LegFrames, quat_multiply, quat_to_matrix, yaw_quat
from symbench.core.data.views.schema import FeatureType
from symbench.core.sim.raw import FLAG_COLUMNS, JOINT_COLUMNS, WORLD_VECTORS
from symbench.core.symmetry import legs as leg_symmetry
from symbench.core.symmetry.groups import GroupElement
from symbench.core.symmetry.legs import MIRROR_Y

_BASE_MAPS: dict[tuple[bytes, bytes, GroupElement, float], np.ndarray] = {}


def base_map(frames: LegFrames, g: GroupElement, tol: float = 1e-9) -> np.ndarray:
    """What g does to the base; refused when the robot's legs lack that symmetry. Kept per
    (frames, element) once checked, read-only: the image overlap acts with each element
    tens of thousands of times, and checking the frames cost a sixth of its time."""
    key = (frames.rotations.tobytes(), frames.origins.tobytes(), g, tol)
    if key not in _BASE_MAPS:
        gb = leg_symmetry.base_map(frames.rotations, frames.origins, g, tol)
        gb.setflags(write=False)
        _BASE_MAPS[key] = gb
    return _BASE_MAPS[key]


def act_on_raw(
    g: GroupElement, raw: Mapping[str, np.ndarray], frames: LegFrames
) -> dict[str, np.ndarray]:
    """g . raw for raw columns shaped (T, ...) (see symbench.core.sim.raw), float64."""
    return _in_raw_order(raw, act_on_legs(g, raw, frames) | act_on_base(g, raw, frames))


def act_on_base(
    g: GroupElement, raw: Mapping[str, np.ndarray], frames: LegFrames
) -> dict[str, np.ndarray]:
    """The base's columns of `act_on_raw(g, raw, frames)` that g changes (a rotation turns
    the base about its own z; a reflection also mirrors the scene); the others are raw's."""
    if not g.reflect:
        return {"base_quat": _turned(raw["base_quat"], -rotation_angle(frames, g))}
    gb = base_map(frames, g)
    angle = np.arctan2(*(gb @ MIRROR_Y)[[1, 0], 0])
    turned = _turned(raw["base_quat"], angle)
    out = {"base_quat": turned * np.array([1.0, -1.0, 1.0, -1.0])}  # conjugated by the mirror
    for name in WORLD_VECTORS:
        out[name] = np.asarray(raw[name], np.float64) @ MIRROR_Y
    out["base_angvel"] = np.asarray(raw["base_angvel"], np.float64) @ -MIRROR_Y
    return out


def rotate_scene_about_gravity(
    raw: Mapping[str, np.ndarray], angle: float
) -> dict[str, np.ndarray]:
    """The same motion with the whole scene turned by `angle` (rad) about world z."""
    return rotate_scene(raw, angle, (0.0, 0.0, 1.0))


def rotate_scene(
    raw: Mapping[str, np.ndarray], angle: float, axis: Sequence[float]
) -> dict[str, np.ndarray]:
    """The robot's states turned by `angle` (rad) about the world `axis` through the origin;
    gravity is not turned. About world z this is a symmetry of the physics; about any other
    axis it tilts the robot against gravity (a change a model's torques must show)."""
    unit = np.asarray(axis, np.float64) / np.linalg.norm(axis)
    quat = np.concatenate([[np.cos(angle / 2)], np.sin(angle / 2) * unit])
    rot = quat_to_matrix(quat)
    out = {k: np.array(v, copy=True) for k, v in raw.items()}
    for name in (*WORLD_VECTORS, "base_angvel"):
        out[name] = np.asarray(raw[name], np.float64) @ rot.T
    out["base_quat"] = quat_multiply(quat, np.asarray(raw["base_quat"], np.float64))
    return out


def rotation_angle(frames: LegFrames, g: GroupElement) -> float:
    """The angle (rad) about the base z that carries each leg i onto leg perm[i], for a
    rotation element (refused when the robot lacks that symmetry)."""
    if g.reflect:
        raise SymbenchError(f"{g.name} is a reflection, not a rotation about the base normal")
    gb = base_map(frames, g)
    return float(np.arctan2(gb[1, 0], gb[0, 0]))


def act_on_legs(
    g: GroupElement, raw: Mapping[str, np.ndarray], frames: LegFrames
) -> dict[str, np.ndarray]:
    """The per-leg columns of `act_on_raw(g, raw, frames)` (joints and flags) alone: what
    comparing joint states needs before the base (`compare`'s early stop)."""
    base_map(frames, g)  # refused when the robot's legs lack the symmetry
    joint_signs = np.asarray(FeatureType.JOINT.reflection_signs) if g.reflect else np.ones(3)
    return _relabelled(raw, g.source_legs(), joint_signs)


def relabel_legs(
    raw: Mapping[str, np.ndarray], source_legs: Any, joint_signs: Any = 1.0
) -> dict[str, np.ndarray]:
    """Per-leg columns relabelled, new leg j = old leg source_legs[j] (joint columns times
    `joint_signs`); the base is left as it is."""
    return _in_raw_order(raw, _relabelled(raw, source_legs, joint_signs))


def _relabelled(
    raw: Mapping[str, np.ndarray], source_legs: Any, joint_signs: Any
) -> dict[str, np.ndarray]:
    src = np.asarray(source_legs, dtype=np.int64)
    joints = {name: np.asarray(raw[name], np.float64)[:, src, :] for name in JOINT_COLUMNS}
    out = {name: column * joint_signs for name, column in joints.items()}
    return out | {name: np.asarray(raw[name])[:, src] for name in FLAG_COLUMNS}


def _in_raw_order(
    raw: Mapping[str, np.ndarray], changed: Mapping[str, np.ndarray]
) -> dict[str, np.ndarray]:
    """`raw`'s columns in its order, those in `changed` replaced, the others copied."""
    return {k: changed[k] if k in changed else np.array(v, copy=True) for k, v in raw.items()}


def turn_base(raw: Mapping[str, np.ndarray], angle: float) -> dict[str, np.ndarray]:
    """The base turned by `angle` (rad) about its own z (the surface normal when it stands
    on the surface); nothing else changes."""
    out = {k: np.array(v, copy=True) for k, v in raw.items()}
    out["base_quat"] = _turned(raw["base_quat"], angle)
    return out


def _turned(base_quat: np.ndarray, angle: float) -> np.ndarray:
    return quat_multiply(np.asarray(base_quat, np.float64), yaw_quat(angle))

"""The raw-trajectory schema: what a robot's sensors and the simulator know, per control step.

The simulator's recorder, the dataset store and `symbench data import` all speak this one
schema; views (leg_grouped, vector, body_graph) are computed from it when loading, never
stored instead of it. World frame: z up, gravity (0, 0, -9.81) for every scene; the slope
is the tilted surface, so rotating a scene about gravity changes only world-frame columns.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from symbench.core.common.errors import SymbenchError

SCHEMA_VERSION = 1


@dataclass(frozen=True)
class RawColumn:
    name: str
    shape: tuple[str, ...]  # per-step shape; "legs" is the robot's leg count
    unit: str
    doc: str


RAW_COLUMNS: tuple[RawColumn, ...] = (
    RawColumn("t", (), "s", "time since the start of the trajectory"),
    RawColumn("base_pos", ("3",), "m", "base origin, world frame"),
    RawColumn("base_quat", ("4",), "", "base orientation, world from base, (w, x, y, z)"),
    RawColumn("base_linvel", ("3",), "m/s", "base origin linear velocity, world frame"),
    RawColumn("base_angvel", ("3",), "rad/s", "base angular velocity, world frame"),
    RawColumn(
        "base_linacc",
        ("3",),
        "m/s^2",
        "base origin linear acceleration, world frame, gravity excluded",
    ),
    RawColumn("q", ("legs", "3"), "rad", "joint positions (coxa, femur, tibia)"),
    RawColumn("qd", ("legs", "3"), "rad/s", "joint velocities"),
    RawColumn("qdd", ("legs", "3"), "rad/s^2", "joint accelerations"),
    RawColumn("tau", ("legs", "3"), "N m", "applied joint torques (after clipping): the target"),
    RawColumn("contact", ("legs",), "0/1", "foot touches the climbing surface"),
    RawColumn("magnet", ("legs",), "0/1", "foot magnet engaged"),
)
COLUMN_NAMES = tuple(c.name for c in RAW_COLUMNS)
# how a symmetry acts on the columns: per-leg joint scalars (a mirror flips some), per-leg
# flags, and world-frame vectors of the base (its angular velocity is a pseudo-vector)
JOINT_COLUMNS = ("q", "qd", "qdd", "tau")
FLAG_COLUMNS = ("contact", "magnet")
WORLD_VECTORS = ("base_pos", "base_linvel", "base_linacc")


def column_shape(col: RawColumn, n_legs: int) -> tuple[int, ...]:
    return tuple(n_legs if s == "legs" else int(s) for s in col.shape)


def validate_raw(arrays: Mapping[str, np.ndarray], n_legs: int, source: str = "trajectory") -> int:
    """Check columns, shapes and finiteness; return the number of steps.

    Every error names the source and the column, so a bad file is found without a debugger.
    """
    missing = [c for c in COLUMN_NAMES if c not in arrays]
    if missing:
        raise SymbenchError(f"{source}: missing column(s) {', '.join(missing)}")
    n_steps = len(arrays["t"])
    for col in RAW_COLUMNS:
        a = np.asarray(arrays[col.name])
        want = (n_steps, *column_shape(col, n_legs))
        if a.shape != want:
            raise SymbenchError(
                f"{source}: column '{col.name}' has shape {a.shape}, expected {want}"
                f" ({n_steps} steps, {n_legs} legs)"
            )
        if not np.all(np.isfinite(a.astype(np.float64))):
            bad = int(np.argwhere(~np.isfinite(a.astype(np.float64).reshape(n_steps, -1)))[0, 0])
            raise SymbenchError(f"{source}: column '{col.name}' has NaN or inf at step {bad}")
    if n_steps > 1 and np.any(np.diff(arrays["t"]) <= 0):
        raise SymbenchError(f"{source}: column 't' is not strictly increasing")
    return n_steps

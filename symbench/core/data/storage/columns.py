"""Raw arrays <-> named scalar columns, the layout of every trajectory file.

One scalar column per component keeps the files readable by any Parquet or pandas user:
`t`, `base_pos.x`, `base_quat.w`, `q.leg0.coxa`, `contact.leg3` and so on. Stored datasets
and `symbench data import` use exactly this layout.
"""

from __future__ import annotations

import re
from collections.abc import Mapping

import numpy as np

from symbench.core.common.errors import SymbenchError, first_of
from symbench.core.sim.raw import RAW_COLUMNS, RawColumn, column_shape

JOINTS = ("coxa", "femur", "tibia")  # a leg's joints, in column and feature order
FLAGS = ("contact", "magnet")
_COMPONENTS = {"3": ("x", "y", "z"), "4": ("w", "x", "y", "z")}
_LEG_JOINT = re.compile(r"^q\.leg(\d+)\.coxa$")


def flat_names(col: RawColumn, n_legs: int) -> list[str]:
    """Scalar column names of `col`, in the row-major order of its per-step shape."""
    if col.shape == ():
        return [col.name]
    if col.shape == ("legs",):
        return [f"{col.name}.leg{i}" for i in range(n_legs)]
    if col.shape == ("legs", "3"):
        return [f"{col.name}.leg{i}.{j}" for i in range(n_legs) for j in JOINTS]
    return [f"{col.name}.{c}" for c in _COMPONENTS[col.shape[0]]]


def all_flat_names(n_legs: int) -> list[str]:
    return [name for col in RAW_COLUMNS for name in flat_names(col, n_legs)]


def flatten(arrays: Mapping[str, np.ndarray], n_legs: int) -> dict[str, np.ndarray]:
    """Shaped raw arrays -> scalar columns (float64; flags as uint8)."""
    out: dict[str, np.ndarray] = {}
    for col in RAW_COLUMNS:
        a = np.asarray(arrays[col.name])
        dtype = np.uint8 if col.name in FLAGS else np.float64
        flat = a.reshape(len(a), -1).astype(dtype)
        for k, name in enumerate(flat_names(col, n_legs)):
            out[name] = np.ascontiguousarray(flat[:, k])
    return out


def unflatten(columns: Mapping[str, np.ndarray], n_legs: int, source: str) -> dict[str, np.ndarray]:
    """Scalar columns -> shaped raw arrays; names the first missing columns if any."""
    missing = [n for n in all_flat_names(n_legs) if n not in columns]
    if missing:
        raise SymbenchError(f"{source}: missing column(s) {first_of(missing, 5)}")
    out = {}
    for col in RAW_COLUMNS:
        names = flat_names(col, n_legs)
        stacked = np.stack([np.asarray(columns[n]) for n in names], axis=-1)
        out[col.name] = stacked.reshape(len(stacked), *column_shape(col, n_legs))
    return out


def check_flags(arrays: Mapping[str, np.ndarray], source: str) -> None:
    """Contact and magnet must be 0 or 1: they are stored as bytes, nothing may be rounded."""
    for flag in FLAGS:
        if not np.isin(np.asarray(arrays[flag]), (0, 1)).all():
            raise SymbenchError(f"{source}: column '{flag}' must hold only 0 and 1")


def legs_in(names: list[str] | tuple[str, ...]) -> int:
    """Number of legs that scalar column names describe (from q.legN.coxa)."""
    found = [int(m.group(1)) for n in names if (m := _LEG_JOINT.match(n))]
    return max(found) + 1 if found else 0

"""One log file of an import folder, read and checked (`symbench data import`): its raw
columns shaped and counted, then completed to every raw column (base vectors in the world
frame, accelerations derived, unknown columns as 0) and checked like a generated trajectory
(schema, finiteness, 0/1 flags, values within float32, the sampling period)."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from symbench.core.common.errors import SymbenchError, first_of
from symbench.core.data.importing.derive import DERIVABLE, UNKNOWABLE, body_to_world, derivative
from symbench.core.data.importing.manifest import IMPORT_JSON, ImportManifest
from symbench.core.data.storage.columns import check_flags, flat_names, legs_in
from symbench.core.data.storage.files import read_columns
from symbench.core.data.storage.npz import read_npz
from symbench.core.sim.raw import COLUMN_NAMES, RAW_COLUMNS, column_shape, validate_raw

PERIOD_TOLERANCE = 0.05  # relative deviation of any time step from record_period_s
LARGEST = float(np.finfo(np.float32).max)  # models compute in float32


def read_log_file(path: Path, n_legs: int, robot: str) -> tuple[dict[str, np.ndarray], list[str]]:
    """The raw columns one log file has, shaped, with the leg count and lengths checked; and
    the names of its other columns (dropped)."""
    if path.suffix == ".parquet":
        columns = read_columns(path)
        found = legs_in(list(columns))
        if found and found != n_legs:
            raise SymbenchError(
                f"{path}: has columns for {found} legs, robot '{robot}' has {n_legs}"
            )
        arrays, known = {}, set()
        for col in RAW_COLUMNS:
            names = flat_names(col, n_legs)
            known.update(names)
            have = [name in columns for name in names]
            if all(have):
                stacked = np.stack([np.asarray(columns[name]) for name in names], axis=-1)
                arrays[col.name] = stacked.reshape(len(stacked), *column_shape(col, n_legs))
            elif any(have):
                missing = [name for name, ok in zip(names, have, strict=True) if not ok]
                raise SymbenchError(f"{path}: missing column(s) {first_of(missing, 5)}")
        return arrays, sorted(set(columns) - known)
    arrays = read_npz(path)
    extra = sorted(k for k in arrays if k not in COLUMN_NAMES)
    arrays = {k: v for k, v in arrays.items() if k in COLUMN_NAMES}
    q = arrays.get("q")
    if q is not None and q.ndim == 3 and q.shape[1] != n_legs:
        raise SymbenchError(f"{path}: 'q' has {q.shape[1]} legs, robot '{robot}' has {n_legs}")

    def steps(a: np.ndarray) -> str:
        return f"{np.shape(a)[0]} steps" if np.ndim(a) else "no time axis"

    if "t" in arrays:
        for name, a in arrays.items():
            if np.shape(a)[:1] != np.shape(arrays["t"])[:1]:
                raise SymbenchError(
                    f"{path}: column '{name}' has {steps(a)} (shape "
                    f"{np.shape(a)}), 't' has {steps(arrays['t'])}"
                )
    return arrays, extra


def _numeric(arrays: dict[str, np.ndarray], source: str) -> dict[str, np.ndarray]:
    """Every raw column as float64; a column of text or objects is named."""
    out = {}
    for name in COLUMN_NAMES:
        if name not in arrays:
            continue
        try:
            out[name] = np.asarray(arrays[name], dtype=np.float64)
        except (TypeError, ValueError):
            raise SymbenchError(
                f"{source}: column '{name}' is not numeric ({np.asarray(arrays[name]).dtype})"
            ) from None
    return out


def check_trajectory(arrays: dict[str, np.ndarray], n_legs: int, period: float, source: str) -> int:
    """Schema, finiteness, 0/1 flags and the sampling period; the number of steps."""
    arrays = _numeric(arrays, source)
    n = validate_raw(arrays, n_legs, source)
    if n < 2:
        raise SymbenchError(f"{source}: {n} step(s); a trajectory needs at least 2")
    for name, values in arrays.items():
        per_step = values.reshape(n, -1)
        huge = np.abs(per_step) > LARGEST
        if huge.any():
            step, column = np.argwhere(huge)[0]
            raise SymbenchError(
                f"{source}: column '{name}' holds {per_step[step, column]:g} at step "
                f"{step}, beyond float32 (±{LARGEST:.3g}), in which models compute"
            )
    check_flags(arrays, source)
    _check_period(arrays["t"], period, source)
    return n


def _check_period(t: np.ndarray, period: float, source: str) -> None:
    dt = np.diff(np.asarray(t, np.float64))
    if len(dt) and np.abs(dt - period).max() > PERIOD_TOLERANCE * period:
        raise SymbenchError(
            f"{source}: time steps range {dt.min():.6g}..{dt.max():.6g} s, but "
            f"{IMPORT_JSON} says record_period_s = {period:g}"
        )


def complete_columns(
    arrays: dict[str, np.ndarray],
    manifest: ImportManifest,
    n_legs: int,
    physics_step: float,
    source: str,
) -> tuple[dict[str, np.ndarray], list[str], list[str]]:
    """Every raw column at the log's rows: base vectors in the world frame, accelerations
    derived when missing, unknown columns as 0; with the derived and the dropped columns."""
    missing = [
        c for c in COLUMN_NAMES if c not in arrays and c not in DERIVABLE and c not in UNKNOWABLE
    ]
    if missing:
        raise SymbenchError(f"{source}: missing column(s) {', '.join(missing)}")
    absent = [c for c in UNKNOWABLE if c not in arrays and c not in manifest.unknown]
    if absent:
        raise SymbenchError(
            f"{source}: missing column(s) {', '.join(absent)}; if the log has no reliable "
            f'{absent[0]}, declare it in {IMPORT_JSON}: "unknown": {json.dumps(absent)}'
        )
    arrays = _numeric(arrays, source)
    n = len(arrays["t"])
    if n < 2:
        raise SymbenchError(f"{source}: {n} step(s); a trajectory needs at least 2")
    if not np.all(np.isfinite(arrays["t"])) or np.any(np.diff(arrays["t"]) <= 0):
        validate_raw({**_zeros_for_missing(arrays, n_legs), **arrays}, n_legs, source)
    _check_period(arrays["t"], manifest.record_period_s, source)
    if manifest.base_frame == "body":
        arrays = body_to_world(arrays)
    derived = []
    for column, source_column in DERIVABLE.items():
        if column not in arrays:
            arrays[column] = derivative(arrays["t"], arrays[source_column], physics_step)
            derived.append(column)
    dropped = []
    for column in manifest.unknown:
        if column in arrays:
            dropped.append(column)
        arrays[column] = np.zeros((n, n_legs))
    return arrays, derived, dropped


def _zeros_for_missing(arrays: dict[str, np.ndarray], n_legs: int) -> dict[str, np.ndarray]:
    n = len(arrays["t"])
    return {
        col.name: np.zeros((n, *column_shape(col, n_legs)))
        for col in RAW_COLUMNS
        if col.name not in arrays
    }

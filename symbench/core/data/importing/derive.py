"""What the importer derives from a log, and how it brings it to the robot's record period.

Everything here matches how the generator (symbench/core/sim/climb/rollout.py) defines its columns:

- **Accelerations.** The generator records, at row time t, qdd = (qd(t + h) - qd(t)) / h and
  base_linacc = (v(t + h) - v(t)) / h, with h the robot's physics step (1 ms) and v the base
  linear velocity in the world frame: the mean acceleration over the physics step that
  follows the row. From a log's rows t_0 < t_1 < ... the importer takes the slope of the
  velocity between consecutive rows, (x_{k+1} - x_k) / (t_{k+1} - t_k), places it at the
  midpoint (t_k + t_{k+1}) / 2, and interpolates these slopes linearly to t_k + h / 2 (the
  midpoint of the generator's interval); the last row takes the last slope. A log recorded at
  every physics step gets exactly the generator's values (plain forward differences); a coarser log
  gets an estimate whose error grows with its period (tests/data/importing/test_derive.py states it:
  about 12-13 % of the RMS acceleration at 3 ms, 20-27 % at 6 ms on a wall climb). No filter is
  applied: the generator's accelerations are unfiltered, and a filter would only
  move the estimate away from them.
- **Resampling.** The generator keeps every 6th physics step (point samples, no filter). A log
  whose period divides the record period (within 5 %) is decimated the same way: every k-th
  row from the first. Any other shorter period is interpolated onto t_0 + n * period: linearly
  for continuous columns, normalised linear interpolation for the quaternion (sign-aligned),
  the previous row's value for the 0/1 flags. A longer period is refused: the `next` variant
  predicts one record period ahead, which a coarser log cannot give.
- **Frames.** Base velocities and accelerations may come in the world frame (the stored one)
  or in the base frame; base-frame vectors are rotated by the row's base orientation
  (v_world = R_wb v_base, R_wb from base_quat, world from base) before anything is derived.
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np

from symbench.core.common.errors import SymbenchError
from symbench.core.data.views.frames import quat_to_matrix

DERIVABLE = {"qdd": "qd", "base_linacc": "base_linvel"}  # derived column: its source
UNKNOWABLE = ("contact", "magnet")  # columns a log may declare unknown
BASE_VECTORS = ("base_linvel", "base_angvel", "base_linacc")  # what base_frame applies to
FLAGS = ("contact", "magnet")
PERIOD_TOLERANCE = 0.05  # relative
MIN_LOG_PERIOD = 1e-6  # s: 1 MHz, beyond any robot's logging


def body_to_world(arrays: Mapping[str, np.ndarray]) -> dict[str, np.ndarray]:
    """Base-frame base vectors rotated into the world frame by each row's base orientation."""
    return _rotate_base_vectors(arrays, "nij,nj->ni")


def world_to_body(arrays: Mapping[str, np.ndarray]) -> dict[str, np.ndarray]:
    """The inverse of `body_to_world` (for tests and exports)."""
    return _rotate_base_vectors(arrays, "nji,nj->ni")  # by R_wb transposed


def _rotate_base_vectors(arrays: Mapping[str, np.ndarray], product: str) -> dict[str, np.ndarray]:
    out = dict(arrays)
    r_wb = quat_to_matrix(np.asarray(arrays["base_quat"], np.float64))
    for name in BASE_VECTORS:
        if name in out:
            out[name] = np.einsum(product, r_wb, np.asarray(out[name], np.float64))
    return out


def _interp_rows(t_src: np.ndarray, x: np.ndarray, t_new: np.ndarray) -> np.ndarray:
    """Rows of `x` (n, ...) at times `t_src` linearly interpolated to `t_new`, clamped."""
    n = len(t_src)
    if n == 1:
        return np.repeat(x[:1], len(t_new), axis=0)
    i = np.clip(np.searchsorted(t_src, t_new, side="right") - 1, 0, n - 2)
    w = np.clip((t_new - t_src[i]) / (t_src[i + 1] - t_src[i]), 0.0, 1.0)
    w = w.reshape(-1, *([1] * (x.ndim - 1)))
    return x[i] * (1.0 - w) + x[i + 1] * w


def derivative(t: np.ndarray, x: np.ndarray, step: float) -> np.ndarray:
    """The generator's (x(t + step) - x(t)) / step at every row, estimated from the rows."""
    t = np.asarray(t, np.float64)
    x = np.asarray(x, np.float64)
    dt = np.diff(t)
    slopes = np.diff(x, axis=0) / dt.reshape(-1, *([1] * (x.ndim - 1)))
    if np.allclose(dt, step, rtol=1e-6, atol=0.0):  # every physics step: the exact formula
        return np.concatenate([slopes, slopes[-1:]])
    return _interp_rows(0.5 * (t[:-1] + t[1:]), slopes, t + 0.5 * step)


def resample_plan(log_period: float, record_period: float) -> tuple[str, int]:
    """("keep", 1), ("decimate", k) or ("interpolate", 0) for a log of `log_period`; an error
    for a period longer than the record period."""
    if log_period < MIN_LOG_PERIOD:  # also keeps record_period / log_period finite
        raise SymbenchError(
            f"record_period_s {log_period:g} s is shorter than {MIN_LOG_PERIOD:g} s: not the "
            "period of a robot's log"
        )
    tolerance = PERIOD_TOLERANCE * record_period
    if abs(log_period - record_period) <= tolerance:
        return "keep", 1
    if log_period > record_period:
        raise SymbenchError(
            f"record_period_s {log_period:g} s is longer than the robot's record period "
            f"{record_period:g} s; symbench does not upsample (the `next` variant predicts "
            f"{record_period:g} s ahead): log at {record_period:g} s or faster"
        )
    k = round(record_period / log_period)
    if abs(k * log_period - record_period) <= tolerance:
        return "decimate", k
    return "interpolate", 0


def resample(arrays: Mapping[str, np.ndarray], log_period: float, record_period: float):
    """`arrays` brought to `record_period`, and a line saying how (None when kept as is)."""
    how, k = resample_plan(log_period, record_period)
    if how == "keep":
        return dict(arrays), None
    n = len(arrays["t"])
    if how == "decimate":
        rows = np.arange(0, n, k)
        out = {name: np.asarray(a)[rows] for name, a in arrays.items()}
        return out, (
            f"decimated from {log_period:g} s to {record_period:g} s: one row in {k} kept, from "
            f"the first, {n - len(rows)} of {n} dropped (point samples, as the generator keeps)"
        )
    t = np.asarray(arrays["t"], np.float64)
    t_new = t[0] + record_period * np.arange(
        int(np.floor((t[-1] - t[0]) / record_period + 1e-9)) + 1
    )
    out = {}
    for name, a in arrays.items():
        a = np.asarray(a, np.float64)
        if name == "t":
            out[name] = t_new
        elif name in FLAGS:
            i = np.clip(np.searchsorted(t, t_new + 1e-12, side="right") - 1, 0, n - 1)
            out[name] = a[i]
        elif name == "base_quat":
            aligned = a.copy()
            for row in range(1, n):  # q and -q are the same rotation: keep neighbours close
                if aligned[row] @ aligned[row - 1] < 0:
                    aligned[row] = -aligned[row]
            q = _interp_rows(t, aligned, t_new)
            out[name] = q / np.linalg.norm(q, axis=-1, keepdims=True)
        else:
            out[name] = _interp_rows(t, a, t_new)
    return out, (
        f"interpolated from {log_period:g} s to {record_period:g} s ({n} rows to "
        f"{len(t_new)}): linear, quaternion normalised, flags held from the previous row"
    )

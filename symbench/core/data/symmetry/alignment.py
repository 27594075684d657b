"""Lining up two logs of one motion on their lift-offs, and comparing them row by row.

Shared by `symbench data symmetry` (report.py, whose docstring states the rule) and the
image-overlap diagnostic (overlap.py): two logs of one motion may start at different phases
of the gait, so both compare each pair over the rows that line up when the flags agree best.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from symbench.core.common.errors import SymbenchError

ALIGN_TOLERANCE = 0.1  # share of rows whose flags may differ in an aligned pair


@dataclass(frozen=True)
class Alignment:
    """How two logs were lined up: row i of the first is row i + `shift` of the second."""

    shift: int = 0
    aligned: bool = True
    how: str = "in phase (no lift-off)"
    flag_mismatch: float | None = None  # share of the compared rows whose flags differ

    def to_dict(self) -> dict[str, Any]:
        return {
            "shift_rows": self.shift,
            "aligned": self.aligned,
            "how": self.how,
            "flag_mismatch": self.flag_mismatch,
        }


def alignment_flag(raw: Mapping[str, np.ndarray], unknown: Sequence[str]) -> str | None:
    """The flag lift-offs are read from: the magnet's, else the contact's (known ones)."""
    for flag in ("magnet", "contact"):
        if flag in raw and flag not in unknown:
            values = np.asarray(raw[flag])
            if np.isfinite(values).all():
                return flag
    return None


def lift_offs(flags: np.ndarray) -> list[tuple[int, int]]:
    """(row, leg) of each lift-off: a row where the leg's flag is 0 after a 1."""
    x = _raised(flags)
    rows, legs = np.nonzero(x[:-1] & ~x[1:])
    return sorted((int(r) + 1, int(leg)) for r, leg in zip(rows, legs))


def _raised(flags: np.ndarray) -> np.ndarray:
    """Flags (T, ...) as booleans (T, n): above 0.5."""
    return np.asarray(flags).reshape(len(flags), -1) > 0.5


@dataclass(frozen=True)
class Flags:
    """A log's flags as `align` reads them, made once (`of`): raised or not per row and leg,
    each row's raised flags as one integer (two rows agree when their codes do) and the
    lift-offs. The image overlap aligns each climb with hundreds of others under every
    group element (`compare.Climbs`): made per comparison, these cost half its time."""

    raised: np.ndarray  # (T, n) booleans
    codes: np.ndarray  # (T,) int64
    lifts: tuple[tuple[int, int], ...]  # (row, leg) of each lift-off, sorted

    @classmethod
    def of(cls, flags: np.ndarray) -> Flags:
        raised = _raised(flags)
        if raised.shape[1] > MOST_FLAGS:
            raise SymbenchError(
                f"a log with {raised.shape[1]} flags per row cannot be aligned (at most "
                f"{MOST_FLAGS})"
            )
        return cls(raised, _codes(raised), tuple(lift_offs(raised)))

    def relabelled(self, source: np.ndarray) -> Flags:
        """The flags with column j taken from column source[j] (a permutation of legs)."""
        raised = self.raised[:, source]
        new_leg = np.argsort(source)
        lifts = sorted((row, int(new_leg[leg])) for row, leg in self.lifts)
        return Flags(raised, _codes(raised), tuple(lifts))

    def __len__(self) -> int:
        return len(self.codes)


MOST_FLAGS = 62  # flags per row that one int64 code holds


def _codes(raised: np.ndarray) -> np.ndarray:
    return raised @ (np.int64(1) << np.arange(raised.shape[1], dtype=np.int64))


def lined_up(n_a: int, n_b: int, shift: int) -> tuple[slice, slice]:
    """The rows of a and of b that line up when row i of a is row i + shift of b."""
    start_a = max(0, -shift)
    rows = max(0, min(n_a - start_a, n_b - (start_a + shift)))
    return slice(start_a, start_a + rows), slice(start_a + shift, start_a + shift + rows)


def _mismatch(x: Flags, y: Flags, shift: int) -> float:
    """The share of the rows lined up at `shift` whose flags differ (1 when none line up)."""
    sx, sy = lined_up(len(x), len(y), shift)
    rows = sx.stop - sx.start
    if not rows:
        return 1.0
    return np.count_nonzero(x.codes[sx] != y.codes[sy]) / rows


def align(x: np.ndarray | Flags | None, y: np.ndarray | Flags | None) -> Alignment:
    """How flag arrays `x` (T, n) and `y` (T', n) of one motion (or their `Flags`) line up
    (see the module's docstring): the shift from x's rows to y's, or why there is none."""
    if x is None or y is None:
        return Alignment(0, False, "flags unknown: compared row by row")
    fx = x if isinstance(x, Flags) else Flags.of(x)
    fy = y if isinstance(y, Flags) else Flags.of(y)
    if not fx.lifts and not fy.lifts:
        return Alignment(0, True, "in phase (no lift-off)", _mismatch(fx, fy, 0))
    first_x: dict[int, int] = {}
    first_y: dict[int, int] = {}
    for row, leg in fx.lifts:
        first_x.setdefault(leg, row)
    for row, leg in fy.lifts:
        first_y.setdefault(leg, row)
    shifts = {0}
    shifts |= {row - first_x[leg] for row, leg in fy.lifts if leg in first_x}
    shifts |= {first_y[leg] - row for row, leg in fx.lifts if leg in first_y}
    least = min(len(fx), len(fy)) / 2
    best: tuple[float, int] | None = None
    for shift in sorted(shifts, key=lambda s: (abs(s), s)):
        sx, _ = lined_up(len(fx), len(fy), shift)
        if sx.stop - sx.start < least:
            continue
        mismatch = _mismatch(fx, fy, shift)
        if best is None or mismatch < best[0]:
            best = (mismatch, shift)
    if best is None or best[0] > ALIGN_TOLERANCE:
        share = _mismatch(fx, fy, 0)
        return Alignment(
            0, False, "flags disagree at every shift tried: compared row by row", share
        )
    mismatch, shift = best
    how = "in phase" if shift == 0 else "on the first lift-off"
    return Alignment(shift, True, how, mismatch)


def aligned_rows(x: np.ndarray, y: np.ndarray, shift: int) -> tuple[np.ndarray, np.ndarray]:
    """The rows of x and of y that line up when row i of x is row i + shift of y."""
    sx, sy = lined_up(len(x), len(y), shift)
    return x[sx], y[sy]


def difference(
    moved: Mapping[str, np.ndarray], b: Mapping[str, np.ndarray], column: str, shift: int = 0
) -> tuple[np.ndarray, np.ndarray]:
    """moved - b over the rows that line up (row i of moved is row i + shift of b), and b's
    values there, flattened per row."""
    x, y = aligned_rows(
        np.asarray(moved[column], np.float64), np.asarray(b[column], np.float64), shift
    )
    rows = len(x)
    if column == "base_quat":  # q and -q are one orientation
        flip = np.sum(x * y, axis=-1, keepdims=True) < 0
        x = np.where(flip, -x, x)
    return (x - y).reshape(rows, -1), y.reshape(rows, -1)


def align_pair(
    a: Mapping[str, np.ndarray], b: Mapping[str, np.ndarray], unknown: Sequence[str]
) -> Alignment:
    """How raw logs a and b line up, on the lift-offs of a flag known in both (row by row
    when there is none)."""
    flag = alignment_flag(b, unknown)
    if flag is None or flag not in a:
        return align(None, None)
    return align(np.asarray(a[flag]), np.asarray(b[flag]))

"""The overlap's screen (`symbench.core.data.symmetry.compare`): every element's joint-state
error of a pair at once, good enough to decide "above".

Nearly every pair stops after the joint states, under each of some 13 elements. Their
squared difference under g is |a|^2 + |b|^2 - 2 sum_j <s * a_src(j), b_j> over the rows that
line up: the norms do not depend on g (it only relabels legs and flips signs), so per pair
and shift one legs x legs matrix of inner products per column and channel (`JointGram`, from
each climb's `Channels`) gives every element's joint error, a mirror's joint signs included,
at the cost of a sum over legs. That expanded form loses digits where the two climbs nearly
agree, so it only decides "above": an element whose screened joint error exceeds the
early-stop threshold by `SCREEN_MARGIN` (many orders of magnitude above its rounding) is
above it.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from symbench.core.data.symmetry.alignment import lined_up
from symbench.core.data.symmetry.report import GROUPS

JOINT_STATES = GROUPS["joint states"]  # the per-leg (T, legs, 3) columns the screen reads
# How far above the early-stop threshold a screened joint error must be to decide "above":
# its rounding is about 1e-13 near the threshold, and at most about 1e-8 where two climbs
# nearly agree (the expanded form's cancellation)
SCREEN_MARGIN = 1e-6


@dataclass(frozen=True)
class Channels:
    """A climb's joint-state columns laid out for `JointGram`: their values as (column,
    channel, leg, row), each legs x rows block contiguous, and per column the running sum of
    each row's squared norm (so a run of rows' sum of squares is one subtraction)."""

    values: np.ndarray  # (column, channel, leg, row)
    squares: np.ndarray  # (column, row + 1)

    @classmethod
    def of(cls, joints: Mapping[str, np.ndarray]) -> Channels:
        columns = np.stack([joints[c] for c in JOINT_STATES])  # (column, row, leg, 3)
        per_row = np.sum(columns * columns, axis=(2, 3))
        squares = np.concatenate([np.zeros((len(columns), 1)), np.cumsum(per_row, axis=1)], 1)
        return cls(np.ascontiguousarray(columns.transpose(0, 3, 2, 1)), squares)


@dataclass(frozen=True)
class JointGram:
    """Per joint-state column, over the rows of a pair that line up: |a|^2 + |b|^2 and, per
    channel, the legs x legs inner products of a's legs with b's; what `Climbs.screen` needs
    for every element (relabelling and joint signs) at that shift."""

    norms: np.ndarray  # (column,)
    products: np.ndarray  # (column, channel, leg of a, leg of b)
    values: int  # values compared per column

    @classmethod
    def of(cls, a: Channels, b: Channels, shift: int) -> JointGram:
        rows_a, rows_b = lined_up(a.values.shape[-1], b.values.shape[-1], shift)
        norms = (
            a.squares[:, rows_a.stop] - a.squares[:, rows_a.start]
            + b.squares[:, rows_b.stop] - b.squares[:, rows_b.start]
        )  # fmt: skip
        products = a.values[..., rows_a] @ b.values[..., rows_b].swapaxes(-1, -2)
        _, channels, legs, _ = a.values.shape
        return cls(norms, products, (rows_a.stop - rows_a.start) * legs * channels)

    def error(self, src: np.ndarray, signs: np.ndarray | None, scales: np.ndarray) -> float:
        """The joint-state group's error of the element taking leg j from a's leg src[j],
        times `signs` per channel (a mirror's; None for a rotation)."""
        if self.values == 0:
            return np.inf
        matched = self.products[:, :, src, np.arange(len(src))].sum(axis=2)  # (column, channel)
        inner = matched.sum(axis=1) if signs is None else matched @ signs
        mean = np.maximum(self.norms - 2.0 * inner, 0.0) / self.values
        return float(np.sqrt(np.mean(mean / scales**2)))

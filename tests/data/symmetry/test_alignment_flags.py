"""`alignment.Flags`, made once per climb (and relabelled per group element) by the image
overlap, aligns exactly as the flag arrays themselves do."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from symbench.core.common.errors import SymbenchError
from symbench.core.data.symmetry.alignment import Flags, align, aligned_rows, lift_offs


@st.composite
def gaits(draw):
    """Two logs of 0/1 flags (rows, legs) with runs of stance and swing, and a relabelling."""
    legs = draw(st.integers(1, 9))
    rng = np.random.default_rng(draw(st.integers(0, 2**32 - 1)))

    def log() -> np.ndarray:
        rows = int(rng.integers(2, 120))
        runs = rng.integers(1, 12, size=(rows, legs)).cumsum(axis=0) // 6 % 2
        return runs.astype(np.float32)

    return log(), log(), rng.permutation(legs)


@settings(max_examples=200, deadline=None)
@given(gaits())
def test_flags_align_as_the_arrays_do(case):
    x, y, source = case
    found = align(x, y)
    assert align(Flags.of(x), Flags.of(y)) == found
    rows_x, rows_y = aligned_rows(x, y, found.shift)  # the mismatch as the module defines it
    differ = np.any((rows_x > 0.5) != (rows_y > 0.5), axis=-1)
    assert found.flag_mismatch == (float(np.mean(differ)) if len(differ) else 1.0)
    moved = Flags.of(x).relabelled(source)
    made = Flags.of(x[:, source])
    assert moved.lifts == made.lifts == tuple(lift_offs(x[:, source]))
    assert np.array_equal(moved.codes, made.codes)
    assert align(moved, Flags.of(y)) == align(x[:, source], y)


def test_a_row_with_more_flags_than_a_code_holds_is_refused():
    with pytest.raises(SymbenchError, match="63 flags per row cannot be aligned"):
        Flags.of(np.zeros((4, 63)))

"""Logarithms with the same bits on every x86-64 CPU, for what is published.

numpy computes float64 `log`, `log10`, `exp` and `power` with its own AVX-512 kernels where
the CPU has them and with the C library's elsewhere, and the two differ in the last bit for
some inputs (measured on an Intel Xeon: the same arrays, two digests). A board must be the
same bytes wherever it is rebuilt (its tests regenerate it), and a last bit can carry a plotted
line across a pixel edge (it did: nona's sample-efficiency PNG, made on an AMD EPYC, failed
on the Xeon) or a rounded figure across its last digit. These take each value from Python's
`math`, i.e. the C library, which has one code path for every CPU with FMA (every x86-64 CPU
with AVX2, with or without AVX-512).
"""

from __future__ import annotations

import math
from collections.abc import Iterable

import numpy as np


def log(values: Iterable[float] | np.ndarray) -> np.ndarray:
    """The natural logarithm of each value, as numpy's: -inf at 0, NaN below it or at NaN."""
    array = np.asarray(values, dtype=float)
    return np.array([_log(x) for x in array.ravel()], dtype=float).reshape(array.shape)


def log10(value: float) -> float:
    """The base-10 logarithm of one value: -inf at 0, NaN below it or at NaN."""
    return math.log10(value) if value > 0 else _log(value)


def _log(x: float) -> float:
    if x > 0:
        return math.log(x)
    return -math.inf if x == 0 else math.nan

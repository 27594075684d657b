"""The two error measures evaluators report, on numpy arrays alone: a plugin that imports
them (`from symbench import rmse`) loads numpy, not the data stack, when the command line
registers it."""

from __future__ import annotations

import numpy as np


def rmse(
    pred: np.ndarray, target: np.ndarray, axis: int | tuple[int, ...] | None = None
) -> np.ndarray:
    """The root mean squared error of `pred` against `target`, over `axis` (all: None)."""
    error: np.ndarray = np.sqrt(np.mean((np.asarray(pred) - np.asarray(target)) ** 2, axis=axis))
    return error


def relative_error(actual: np.ndarray, expected: np.ndarray) -> float:
    """max |actual - expected| / max |expected|: how far two torque predictions differ,
    relative to their size (the equivariance kit and the evaluators share it)."""
    actual, expected = np.asarray(actual), np.asarray(expected)
    scale = float(np.max(np.abs(expected))) if expected.size else 0.0
    return float(np.max(np.abs(actual - expected))) / max(scale, np.finfo(np.float64).tiny)

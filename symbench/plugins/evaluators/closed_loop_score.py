"""The closed loop's continuous score (symbench/plugins/evaluators/closed_loop.py).

Per reference, the model's tracking cost (`Tracking.tracking_cost`: its joint error
accumulated over the horizon, each step after a fall counting as fully lost) placed between
the floor's (0) and the oracle's (1); over the references, the mean and a 95 % percentile
bootstrap interval (references resampled, a fixed seed: the same record gives the same
interval). Unlike the time held it does not snap to gait events: a model that falls one
step later, or tracks a little better before it falls, scores a little higher.
"""

from __future__ import annotations

import numpy as np

# below this span of tracking cost between floor and oracle the PD alone tracks the
# reference (the servo gains' fraction 1), and a score there would amplify rounding
MIN_SPAN = 0.05
RESAMPLES = 2000
CONFIDENCE = 0.95


def reference_score(model: float, floor: float, oracle: float) -> float | None:
    """0 at the floor's cost, 1 at the oracle's, linear (and so monotone) in the model's;
    None where floor and oracle are within MIN_SPAN of each other."""
    span = floor - oracle
    if not span > MIN_SPAN:
        return None
    return float((floor - model) / span)


def mean_interval(scores: list[float | None]) -> tuple[float | None, list[float] | None]:
    """The mean of the defined scores and its 95 % bootstrap interval over references
    (None, None when none is defined)."""
    values = np.array([s for s in scores if s is not None], dtype=np.float64)
    if not len(values):
        return None, None
    rng = np.random.default_rng(0)
    means = values[rng.integers(len(values), size=(RESAMPLES, len(values)))].mean(axis=1)
    tail = 100.0 * (1.0 - CONFIDENCE) / 2.0
    low, high = np.percentile(means, [tail, 100.0 - tail])
    return float(values.mean()), [float(low), float(high)]

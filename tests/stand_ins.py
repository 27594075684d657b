"""Stand-ins shared by the evaluator tests: trained models that cost nothing."""

from __future__ import annotations

import numpy as np

from symbench.core.common.arrays import ViewArrays
from symbench.core.runs.evaluation import TrainedOnSplit


def trained_on_split(split: str, variant: str) -> TrainedOnSplit:
    """A 'model' of six legs predicting zero torques, with a two-sample test set of ones."""
    test = ViewArrays(
        "leg_grouped",
        variant,
        6,
        {"x": np.zeros((2, 6, 1))},
        np.ones((2, 6, 3)),
        np.zeros(2, dtype=np.int64),
    )
    return TrainedOnSplit(split, variant, lambda inputs: np.zeros((2, 6, 3)), test)

"""A trained model as the closed loop's controller: the policy `track_batch` calls."""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from symbench.core.data.views.frames import LegFrames
from symbench.core.data.views.transforms import build_view
from symbench.core.sim.tracking.learned_control import BatchPolicy


def feedforward_policy(
    predict: Callable[[dict[str, np.ndarray]], np.ndarray], frames: LegFrames, view: str
) -> BatchPolicy:
    """A trained model (`predict` on `view` inputs, trained on the `next` variant) as the
    batch policy of `track_batch`: each pair of rows is one sample; `frames` are the
    dataset's."""
    pairs: dict[int, np.ndarray] = {}

    def policy(rows: dict[str, np.ndarray]) -> np.ndarray:
        n = len(rows["t"])
        if n not in pairs:
            pairs[n] = np.repeat(np.arange(n // 2), 2)
        return predict(build_view(rows, pairs[n], frames, view, "next").inputs)

    return policy

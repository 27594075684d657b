"""The names of the training protocols and of the reasons a training stops: one definition
for the loop that applies them, the records that keep them and the commands that offer them
(the loop itself is `symbench.core.training.loop`)."""

from __future__ import annotations

import math
from typing import Literal, get_args

import numpy as np

Protocol = Literal["converge", "cosine", "paper"]
PROTOCOLS: tuple[str, ...] = get_args(Protocol)
# the protocols with a budget of gradient steps and a patience in validation checks (paper:
# an epoch cap and the paper's overfitting rule)
STEP_BUDGET: tuple[str, ...] = ("converge", "cosine")
# why a training stopped: patience or budget (converge, cosine), overfitting-rule or epoch-cap
# (paper)
StoppedBy = Literal["patience", "budget", "overfitting-rule", "epoch-cap"]


def rate_scale(protocol: str, steps: range, max_steps: int) -> np.ndarray:
    """The learning rate of each gradient step in `steps`, as a multiple of the model's:
    1 throughout (converge, paper), or a half cosine from 1 at step 0 to 0 at the budget
    (cosine), so the last steps take small ones and settle instead of hovering at the noise
    floor of a constant rate. A function of the step index only: a resumed training continues
    on the same curve."""
    if protocol != "cosine":
        return np.ones(len(steps))
    return np.array([0.5 * (1.0 + math.cos(math.pi * s / max_steps)) for s in steps])

"""The names of the training protocols and of the reasons a training stops: one definition
for the loop that applies them, the records that keep them and the commands that offer them
(the loop itself is `symbench.core.training.loop`)."""

from __future__ import annotations

from typing import Literal, get_args

Protocol = Literal["converge", "paper"]
PROTOCOLS: tuple[str, ...] = get_args(Protocol)
# why a training stopped: patience or budget (converge), overfitting-rule or epoch-cap (paper)
StoppedBy = Literal["patience", "budget", "overfitting-rule", "epoch-cap"]

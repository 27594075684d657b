"""The training protocols: their names, the reasons a training stops, and each protocol's
settings as one frozen, typed object, so that a setting of one protocol cannot be given to
another. One definition for the loop that applies them, the records that keep them and the
commands that offer them (the loop itself is `symbench.core.training.loop`)."""

from __future__ import annotations

import math
from dataclasses import dataclass, fields
from typing import TYPE_CHECKING, ClassVar, Literal, get_args

import numpy as np

from symbench.core.common.errors import SymbenchError

if TYPE_CHECKING:
    from symbench.core.config.presets import Training

Protocol = Literal["converge", "cosine", "paper"]
PROTOCOLS: tuple[str, ...] = get_args(Protocol)
# the protocols with a budget of gradient steps and a patience in validation checks (paper:
# an epoch cap and the paper's overfitting rule)
STEP_BUDGET: tuple[str, ...] = ("converge", "cosine")
# why a training stopped: patience or budget (converge, cosine), overfitting-rule or epoch-cap
# (paper)
StoppedBy = Literal["patience", "budget", "overfitting-rule", "epoch-cap"]


def _at_least_one(settings: object, names: tuple[str, ...]) -> None:
    for name in names:
        value = getattr(settings, name)
        if value < 1:
            raise SymbenchError(f"TrainConfig.{name} must be at least 1, got {value}")


@dataclass(frozen=True)
class Converge:
    """`converge`: at most `max_steps` gradient steps; the validation loss is checked every
    `eval_every` steps, and training stops when it has not improved for `patience` checks."""

    max_steps: int = 10000
    eval_every: int = 500
    patience: int = 6
    name: ClassVar[Protocol] = "converge"

    def __post_init__(self) -> None:
        _at_least_one(self, ("max_steps", "eval_every", "patience"))


@dataclass(frozen=True)
class Cosine(Converge):
    """`cosine`: `converge`'s settings, the learning rate decayed along a half cosine to zero
    at `max_steps` (`rate_scale`)."""

    name: ClassVar[Protocol] = "cosine"


@dataclass(frozen=True)
class Paper:
    """`paper`: one check per epoch; stop when `stop_ratio` x validation loss exceeds the
    training loss `stop_patience` epochs in a row, or at `max_epochs`."""

    max_epochs: int = 200
    stop_ratio: float = 0.7
    stop_patience: int = 5
    name: ClassVar[Protocol] = "paper"

    def __post_init__(self) -> None:
        _at_least_one(self, ("max_epochs", "stop_patience"))


# one protocol's settings; `Cosine` is a `Converge` (a step budget), `Paper` is not
Schedule = Converge | Cosine | Paper
SCHEDULES: dict[str, type[Converge] | type[Paper]] = {
    "converge": Converge,
    "cosine": Cosine,
    "paper": Paper,
}
# the settings of each family, in the order the flat record layout lists them
STEP_SETTINGS = tuple(f.name for f in fields(Converge))
EPOCH_SETTINGS = tuple(f.name for f in fields(Paper))


def schedule_class(protocol: str) -> type[Converge] | type[Paper]:
    """The settings class of the protocol named `protocol`; an unknown name is refused."""
    if protocol not in SCHEDULES:
        raise SymbenchError(f"unknown training protocol '{protocol}' ({', '.join(PROTOCOLS)})")
    return SCHEDULES[protocol]


def preset_schedules(
    protocol: str,
    budget: Training,
    max_steps: int | None = None,
    max_epochs: int | None = None,
) -> tuple[Schedule, Converge | Paper]:
    """(the protocol's settings, the other family's) with the preset's budgets, `max_steps`
    (converge, cosine) or `max_epochs` (paper) replacing its own; a budget of another
    protocol is refused, not ignored. The other family's settings are unused by training:
    the flat record layout keeps them (`TrainConfig.to_dict`)."""
    cls = schedule_class(protocol)
    paper = cls is Paper
    own, other, option = (
        (max_epochs, max_steps, "--max-steps") if paper else (max_steps, max_epochs, "--max-epochs")
    )
    if other is not None:
        raise SymbenchError(
            f"{option} is a budget of another protocol, not of "
            f"'{protocol}' (converge, cosine: --max-steps; paper: --max-epochs)"
        )
    steps = budget.max_steps if paper or own is None else own
    epochs = budget.max_epochs if not paper or own is None else own
    converge = (Cosine if cls is Cosine else Converge)(steps, budget.eval_every, budget.patience)
    return (Paper(epochs), converge) if paper else (converge, Paper(epochs))


def rate_scale(protocol: str, steps: range, max_steps: int) -> np.ndarray:
    """The learning rate of each gradient step in `steps`, as a multiple of the model's:
    1 throughout (converge, paper), or a half cosine from 1 at step 0 to 0 at the budget
    (cosine), so the last steps take small ones and settle instead of hovering at the noise
    floor of a constant rate. A function of the step index only: a resumed training continues
    on the same curve."""
    if protocol != "cosine":
        return np.ones(len(steps))
    return np.array([0.5 * (1.0 + math.cos(math.pi * s / max_steps)) for s in steps])

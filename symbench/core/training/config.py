"""`TrainConfig`: one training's settings, its protocol's typed and those every protocol
shares, and the flat layout in which records and resume checkpoints keep them."""

from __future__ import annotations

import copy
from dataclasses import dataclass, field
from typing import Any

from symbench.core.common.errors import SymbenchError
from symbench.core.common.seeds import check_seed
from symbench.core.config.protocols import (
    EPOCH_SETTINGS,
    STEP_SETTINGS,
    Converge,
    Cosine,
    Paper,
    Schedule,
    schedule_class,
)
from symbench.core.plugin.entries import ModelEntry

__all__ = ["Converge", "Cosine", "Paper", "Schedule", "TrainConfig"]

# the settings of a protocol, which TrainConfig takes as one typed object (`schedule=`)
_FLAT = frozenset(("protocol", *STEP_SETTINGS, *EPOCH_SETTINGS))


@dataclass(frozen=True)
class TrainConfig:
    """One training's settings: the protocol's own (`schedule`: `Converge`, `Cosine` or
    `Paper`) and those every protocol shares. `unused`: the other protocol family's settings,
    which the flat layout of records and checkpoints (`to_dict`) also lists; training never
    reads them (a run: the preset's; None: the defaults)."""

    schedule: Schedule = field(default_factory=Converge)
    seed: int = 0
    batch_size: int = 64
    val_stride: int = 1  # validation checks use every val_stride-th row of each held-out climb
    # None: the model entry's learning rate (a run's: its robot's tuned one, `train_config`)
    learning_rate: float | None = None
    hyper: dict[str, Any] = field(default_factory=dict)  # network sizes, passed to build
    compile: bool | None = None  # None: the backend's faster default (see `bench models`)
    progress: bool = True
    unused: Converge | Paper | None = None

    def __new__(cls, *args: Any, **kwargs: Any) -> TrainConfig:
        flat = sorted(_FLAT & set(kwargs))
        if flat:  # the flat keywords of before the typed protocols
            raise SymbenchError(
                f"TrainConfig takes a protocol's settings as one object now: not "
                f"TrainConfig({flat[0]}=...) but TrainConfig(schedule=Converge(max_steps=..., "
                "eval_every=..., patience=...)), Cosine(...) or Paper(max_epochs=..., "
                "stop_ratio=..., stop_patience=...) (from symbench import Converge, Cosine, Paper)"
            )
        return super().__new__(cls)

    def __post_init__(self) -> None:
        check_seed(self.seed, "TrainConfig.seed")
        if not isinstance(self.schedule, (Converge, Paper)):
            raise SymbenchError(
                f"TrainConfig.schedule must be Converge, Cosine or Paper, got {self.schedule!r}"
            )
        if self.unused is not None and (
            isinstance(self.unused, Converge) == isinstance(self.schedule, Converge)
        ):
            raise SymbenchError("TrainConfig.unused must be the other protocol family's settings")
        for name in ("batch_size", "val_stride"):
            if getattr(self, name) < 1:
                raise SymbenchError(
                    f"TrainConfig.{name} must be at least 1, got {getattr(self, name)}"
                )
        if self.learning_rate is not None and not self.learning_rate > 0:
            raise SymbenchError(
                f"TrainConfig.learning_rate must be positive, got {self.learning_rate}"
            )

    @property
    def protocol(self) -> str:
        return self.schedule.name

    @property
    def steps_and_epochs(self) -> tuple[Converge, Paper]:
        """(the step-budget settings, the paper's): the schedule's own and `unused`."""
        own, other = self.schedule, self.unused
        if isinstance(own, Converge):
            return own, other if isinstance(other, Paper) else Paper()
        return (other if isinstance(other, Converge) else Converge()), own

    def to_dict(self) -> dict[str, Any]:
        """The settings that shape the trained model, in the flat layout records and resume
        checkpoints keep (the progress bar is left out, so that a model's content hash is the
        same with or without one). `val_stride` is left out at 1, so that records and resume
        checkpoints made before it existed still match."""
        steps, epochs = self.steps_and_epochs
        stride = {"val_stride": self.val_stride} if self.val_stride != 1 else {}
        return {
            "seed": self.seed,
            "batch_size": self.batch_size,
            "protocol": self.protocol,
            **{name: getattr(steps, name) for name in STEP_SETTINGS},
            **stride,
            **{name: getattr(epochs, name) for name in EPOCH_SETTINGS},
            "learning_rate": self.learning_rate,
            "hyper": copy.deepcopy(self.hyper),
            "compile": self.compile,
        }

    @classmethod
    def from_dict(cls, flat: dict[str, Any], progress: bool = True) -> TrainConfig:
        """The configuration whose `to_dict` is `flat` (a record's, `symbench verify`)."""
        protocol = flat["protocol"]
        schedule_class(protocol)  # an unknown name is refused
        steps = [flat[name] for name in STEP_SETTINGS]
        epochs = Paper(*(flat[name] for name in EPOCH_SETTINGS))
        own: Schedule = (Cosine if protocol == "cosine" else Converge)(*steps)
        return cls(
            schedule=epochs if protocol == "paper" else own,
            unused=Converge(*steps) if protocol == "paper" else epochs,
            progress=progress,
            **{k: flat[k] for k in ("seed", "batch_size", "learning_rate", "hyper", "compile")},
            val_stride=flat.get("val_stride", 1),
        )

    def rate_for(self, entry: ModelEntry) -> float:
        """The learning rate a training of `entry` uses: this config's, else the model's."""
        return entry.learning_rate if self.learning_rate is None else self.learning_rate

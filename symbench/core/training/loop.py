"""One training protocol for every model and backend (docs/concepts.md, Training).

Adam, batch 64, the model's learning rate, MSE on normalized targets; stop when
`stop_ratio` x validation loss exceeds the training loss `stop_patience` epochs in a row,
or at `max_epochs`; keep the parameters with the best validation loss. Everything random
(initialization, batch order) derives from the seed, and the batch order of epoch k depends
on (seed, k) only, so a training resumed from its last checkpoint continues exactly as if it
had never stopped. The checkpoint folder, and what a resumed run may trust, is `resume`'s.
"""

from __future__ import annotations

import hashlib
import math
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
from rich.progress import (
    BarColumn,
    MofNCompleteColumn,
    Progress,
    TextColumn,
    TimeElapsedColumn,
    TimeRemainingColumn,
)

from symbench.core.common.arrays import ViewArrays
from symbench.core.common.errors import SymbenchError
from symbench.core.common.seeds import check_seed
from symbench.core.data.model_dims import ModelDims, dims_of
from symbench.core.plugin.entries import ModelEntry
from symbench.core.training import resume
from symbench.core.training.backends import get_backend
from symbench.core.training.normalization import Normalizer
from symbench.core.training.trained_model import TrainedModel


@dataclass(frozen=True)
class TrainConfig:
    seed: int = 0
    batch_size: int = 64
    max_epochs: int = 200
    stop_ratio: float = 0.7
    stop_patience: int = 5
    learning_rate: float | None = None  # None: the model entry's learning rate
    hyper: dict[str, Any] = field(default_factory=dict)  # network sizes, passed to build
    compile: bool | None = None  # None: the backend's faster default (see `bench models`)
    progress: bool = True

    def __post_init__(self) -> None:
        check_seed(self.seed, "TrainConfig.seed")
        for name in ("batch_size", "max_epochs", "stop_patience"):
            if getattr(self, name) < 1:
                raise SymbenchError(
                    f"TrainConfig.{name} must be at least 1, got {getattr(self, name)}"
                )
        if self.learning_rate is not None and not self.learning_rate > 0:
            raise SymbenchError(
                f"TrainConfig.learning_rate must be positive, got {self.learning_rate}"
            )

    def to_dict(self) -> dict[str, Any]:
        """The settings that shape the trained model (the progress bar does not, so that a
        model's content hash is the same with or without one)."""
        return {k: v for k, v in asdict(self).items() if k != "progress"}

    def rate_for(self, entry: ModelEntry) -> float:
        """The learning rate a training of `entry` uses: this config's, else the model's."""
        return entry.learning_rate if self.learning_rate is None else self.learning_rate


@dataclass
class _Progress:
    """What the resume checkpoint records besides the parameters and optimizer state."""

    epoch: int = 0
    train_loss: list[float] = field(default_factory=list)
    val_loss: list[float] = field(default_factory=list)
    best_epoch: int = -1
    strikes: int = 0
    stopped: str = ""

    @property
    def best_val(self) -> float:
        return self.val_loss[self.best_epoch] if self.best_epoch >= 0 else math.inf


def batch_order(n: int, batch_size: int, seed: int, epoch: int) -> np.ndarray:
    """(n_batches, batch) indices of one epoch: a fresh permutation, the remainder dropped."""
    batch = min(batch_size, n)
    perm = np.random.default_rng([seed, epoch]).permutation(n)
    n_batches = n // batch
    return perm[: n_batches * batch].reshape(n_batches, batch)


def train(
    entry: ModelEntry,
    train: ViewArrays,
    val: ViewArrays,
    config: TrainConfig,
    checkpoint_dir: Path | None = None,
) -> TrainedModel:
    """Train `entry` on `train`, select on `val`; resume from `checkpoint_dir` when it holds one."""
    dims = _check_data(entry, train, val)
    normalizer = Normalizer.fit(train)
    backend = get_backend(entry.backend)
    compiled = backend.default_compiled if config.compile is None else config.compile
    lr = config.rate_for(entry)
    identity = _identity(entry, dims, config, train, val)
    params = backend.init_params(entry, dims, config.hyper, config.seed)
    trainer = backend.make_trainer(entry, dims, config.hyper, params, lr, compiled)
    trainer.set_data(
        normalizer.normalize_inputs(train.inputs),
        normalizer.normalize("target", train.target),
        normalizer.normalize_inputs(val.inputs),
        normalizer.normalize("target", val.target),
    )
    state, best = _Progress(), params

    def result() -> TrainedModel:
        history = {"train_loss": state.train_loss, "val_loss": state.val_loss}
        return TrainedModel(
            entry,
            dims,
            dict(config.hyper),
            normalizer,
            best,
            history,
            state.best_epoch,
            config.to_dict(),
            state.stopped,
        )

    resumed = _resume(Path(checkpoint_dir), identity, trainer, config) if checkpoint_dir else None
    if resumed is not None and checkpoint_dir:
        state, best = resumed
        resume.check_best(Path(checkpoint_dir), result())

    with _progress_bar(config, entry) as bar:
        task = bar.add_task(
            "train",
            total=config.max_epochs,
            completed=state.epoch,
            loss="",
            name=f"{entry.name}/{entry.backend}",
        )
        while not state.stopped:
            train_loss = trainer.train_epoch(
                batch_order(len(train), config.batch_size, config.seed, state.epoch)
            )
            val_loss = trainer.val_loss()
            if not (math.isfinite(train_loss) and math.isfinite(val_loss)):
                raise SymbenchError(
                    f"{entry.name}/{entry.backend}: loss became {train_loss} "
                    f"(train) / {val_loss} (val) in epoch {state.epoch}; "
                    "lower the learning rate"
                )
            state.train_loss.append(train_loss)
            state.val_loss.append(val_loss)
            if val_loss < state.best_val:
                state.best_epoch, best = state.epoch, trainer.params()
            state.strikes = state.strikes + 1 if config.stop_ratio * val_loss > train_loss else 0
            state.epoch += 1
            state.stopped = _stop_reason(state, config)
            if checkpoint_dir is not None:
                _save(Path(checkpoint_dir), identity, state, trainer, result())
            bar.update(
                task,
                completed=state.epoch,
                loss=f"train {train_loss:.4g}  val {val_loss:.4g}  best {state.best_val:.4g}",
            )
    return result()


def _stop_reason(state: _Progress, config: TrainConfig) -> str:
    if state.strikes >= config.stop_patience:
        return (
            f"{config.stop_ratio} x validation loss exceeded the training loss "
            f"{config.stop_patience} epochs in a row"
        )
    if state.epoch >= config.max_epochs:
        return f"reached max_epochs={config.max_epochs}"
    return ""


def _check_data(entry: ModelEntry, train: ViewArrays, val: ViewArrays) -> ModelDims:
    for name, data in (("training", train), ("validation", val)):
        if (data.view, data.variant) != (entry.view, entry.variant):
            raise SymbenchError(
                f"model {entry.name} consumes the {entry.view}/{entry.variant} view; "
                f"the {name} data is {data.view}/{data.variant}"
            )
        if len(data) == 0:
            raise SymbenchError(f"the {name} data is empty")
    dims = dims_of(train)
    if dims_of(val) != dims:
        raise SymbenchError("training and validation data come from robots with different legs")
    if not np.isfinite(val.target).all() or not all(
        np.isfinite(v).all() for v in val.inputs.values()
    ):
        raise SymbenchError("validation data holds NaN or infinite values")
    return dims


def _identity(
    entry: ModelEntry, dims: ModelDims, config: TrainConfig, train: ViewArrays, val: ViewArrays
) -> dict[str, Any]:
    """What a resume checkpoint must match: the same model, protocol and data (by content,
    so a regenerated dataset of the same size does not resume an old training)."""
    cfg = {k: v for k, v in config.to_dict().items() if k != "max_epochs"}
    return {
        "model": entry.name,
        "backend": entry.backend,
        "variant": entry.variant,
        "dims": dims.to_dict(),
        "config": cfg,
        "n_train": len(train),
        "n_val": len(val),
        "data_sha256": _fingerprint(train, val),
    }


def _fingerprint(*parts: ViewArrays) -> str:
    digest = hashlib.sha256()
    for arrays in parts:
        for key in sorted(arrays.inputs):
            digest.update(np.ascontiguousarray(arrays.inputs[key]).tobytes())
        digest.update(np.ascontiguousarray(arrays.target).tobytes())
    return digest.hexdigest()


def _save(
    folder: Path, identity: dict, state: _Progress, trainer: Any, model: TrainedModel
) -> None:
    """The epoch's resume checkpoint; `best/` when this epoch is the best or the last, so
    that a finished run's `best/` is the model `train` returns."""
    improved = state.best_epoch == state.epoch - 1
    groups = {
        "params": trainer.params(),
        "optimizer": trainer.optimizer_state(),
        "best": model.params,
    }
    resume.save(
        folder,
        groups,
        {"identity": identity, "progress": asdict(state)},
        model if improved or state.stopped else None,
    )


def _resume(folder: Path, identity: dict, trainer: Any, config: TrainConfig):
    """(progress, best parameters) from the newest good resume checkpoint, the trainer
    loaded with its state; None when there is none."""
    loaded = resume.load(folder)
    if loaded is None:
        return None
    groups, saved = loaded
    if not isinstance(saved, dict) or saved.get("identity") != identity:
        raise SymbenchError(
            f"{folder} holds a training of another model, data or configuration; "
            "use a fresh checkpoint folder"
        )
    state = _Progress(**saved["progress"])
    state.stopped = _stop_reason(state, config)  # a larger max_epochs continues a capped run
    trainer.load_params(groups["params"])
    trainer.load_optimizer_state(groups["optimizer"])
    return state, groups["best"]


def _progress_bar(config: TrainConfig, entry: ModelEntry) -> Progress:
    return Progress(
        TextColumn("{task.fields[name]}"),
        BarColumn(),
        MofNCompleteColumn(),
        TextColumn("epochs"),
        TextColumn("{task.fields[loss]}"),
        TimeElapsedColumn(),
        TextColumn("at most"),
        TimeRemainingColumn(),  # from the epoch cap: early stopping only shortens it
        disable=not config.progress,
        transient=False,
    )

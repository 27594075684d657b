"""The training protocols, the same for every model and backend (docs/concepts.md, Training).

All three: Adam, batch 64, the model's learning rate, MSE on normalized targets, validation
on trajectories held out of the training side, and the parameters with the best validation
loss kept. They differ in when training stops and in how the learning rate moves:

- `converge` (the default): a budget of `max_steps` gradient steps, the same for every model
  and every training fraction; the validation loss is checked every `eval_every` steps, and
  training stops early when it has not improved for `patience` checks in a row. Every model
  thus trains until it stops improving on data like its training data, or up to the budget.
- `cosine`: `converge` with the learning rate decayed along a half cosine from the model's
  rate to zero over the budget (`protocols.rate_scale`): at a constant rate a model hovers
  at a noise floor its rate sets (hexa `small`, 10 000 steps: sdnn's validation loss 7
  times lower with cosine, ffnn's 7 % lower; docs/concepts.md, Training).
- `paper`: the paper's rule, one check per epoch; stop when `stop_ratio` x validation loss
  exceeds the training loss `stop_patience` epochs in a row, or at `max_epochs`. It stops any
  model whose validation data is harder than its training data (what a model that lacks the
  robot's symmetry always sees), and a smaller training fraction gets fewer updates.

Everything random (initialization, batch order) derives from the seed: the batch order of
data pass k depends on (seed, k) only, and gradient step s is batch s mod (batches per
pass) of pass s div (batches per pass), so a training resumed from its last checkpoint
continues exactly as if it had never stopped. The checkpoint folder, and what a resumed run
may trust, is `resume`'s.
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
from symbench.core.config.protocols import Converge, Paper, rate_scale
from symbench.core.data.views.model_dims import ModelDims, dims_of
from symbench.core.plugin.entries import ModelEntry
from symbench.core.training import resume
from symbench.core.training.backends import get_backend
from symbench.core.training.config import TrainConfig
from symbench.core.training.normalization import Normalizer
from symbench.core.training.trained_model import TrainedModel


@dataclass
class _Progress:
    """What the resume checkpoint records besides the parameters and optimizer state.
    `epoch` counts validation checks (one per epoch under `paper`), `best_epoch` is the
    check of the best parameters."""

    epoch: int = 0
    train_loss: list[float] = field(default_factory=list)
    val_loss: list[float] = field(default_factory=list)
    best_epoch: int = -1
    strikes: int = 0
    stopped: str = ""
    steps: int = 0  # gradient steps taken
    best_step: int = 0  # gradient steps taken when the best parameters were
    stopped_by: str = ""  # a protocols.StoppedBy once stopped

    @property
    def best_val(self) -> float:
        return self.val_loss[self.best_epoch] if self.best_epoch >= 0 else math.inf


def batches_per_epoch(n: int, batch_size: int) -> int:
    """Full batches in one pass over `n` samples (the remainder is dropped)."""
    return n // min(batch_size, n)


def batch_order(n: int, batch_size: int, seed: int, epoch: int) -> np.ndarray:
    """(n_batches, batch) indices of one epoch: a fresh permutation, the remainder dropped."""
    n_batches = batches_per_epoch(n, batch_size)
    perm = np.random.default_rng([seed, epoch]).permutation(n)
    return perm[: n_batches * min(batch_size, n)].reshape(n_batches, -1)


def round_batches(n: int, config: TrainConfig, state: _Progress) -> np.ndarray:
    """The batches between this validation check and the next: one epoch under `paper`;
    under `converge` the next `eval_every` gradient steps (at most up to the budget) of the
    stream of epochs, so a check may fall in the middle of one."""
    budget = config.schedule
    if isinstance(budget, Paper):
        return batch_order(n, config.batch_size, config.seed, state.epoch)
    per_epoch = batches_per_epoch(n, config.batch_size)
    steps = range(state.steps, min(state.steps + budget.eval_every, budget.max_steps))
    epochs = {s // per_epoch for s in steps}
    orders = {e: batch_order(n, config.batch_size, config.seed, e) for e in epochs}
    return np.stack([orders[s // per_epoch][s % per_epoch] for s in steps])


def train(
    entry: ModelEntry,
    train: ViewArrays,
    val: ViewArrays,
    config: TrainConfig,
    checkpoint_dir: Path | None = None,
) -> TrainedModel:
    """Train `entry` on `train`, select on `val` (every `config.val_stride`-th row: rows of a
    climb 6 ms apart carry nearly the same error, so a large preset's checks thin them out
    instead of checking less often); resume from `checkpoint_dir` when it holds one."""
    dims = _check_data(entry, train, val)
    if config.val_stride > 1:  # stride 1: the rows as given, no copy
        val = val.take(np.arange(0, len(val), config.val_stride))
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
            state.stopped_by,
            state.steps,
            state.best_step,
        )

    resumed = _resume(Path(checkpoint_dir), identity, trainer, config) if checkpoint_dir else None
    if resumed is not None and checkpoint_dir:
        state, best = resumed
        resume.check_best(Path(checkpoint_dir), result())

    with _progress_bar(config, entry) as bar:
        task = bar.add_task(
            "train",
            total=_bar_total(config, len(train)),
            completed=state.steps,
            loss="",
            name=f"{entry.name}/{entry.backend}",
        )
        while not state.stopped:
            batches = round_batches(len(train), config, state)
            steps = range(state.steps, state.steps + len(batches))
            train_loss = trainer.train_epoch(
                batches, rate_scale(config.protocol, steps, config.steps_and_epochs[0].max_steps)
            )
            val_loss = trainer.val_loss()
            if not (math.isfinite(train_loss) and math.isfinite(val_loss)):
                raise SymbenchError(
                    f"{entry.name}/{entry.backend}: loss became {train_loss} "
                    f"(train) / {val_loss} (val) in epoch {state.epoch}; "
                    "lower the learning rate"
                )
            state.train_loss.append(train_loss)
            state.steps += len(batches)
            improved = val_loss < state.best_val
            state.val_loss.append(val_loss)
            if improved:
                state.best_epoch, state.best_step, best = state.epoch, state.steps, trainer.params()
            state.strikes = _strikes(state, config, improved, train_loss, val_loss)
            state.epoch += 1
            state.stopped_by, state.stopped = _stop_reason(state, config)
            if checkpoint_dir is not None:
                _save(Path(checkpoint_dir), identity, state, trainer, result())
            bar.update(
                task,
                completed=state.steps,
                loss=f"train {train_loss:.4g}  val {val_loss:.4g}  best {state.best_val:.4g}",
            )
    return result()


def _strikes(
    state: _Progress, config: TrainConfig, improved: bool, train_loss: float, val_loss: float
) -> int:
    """Checks in a row that count towards stopping: without improvement (`converge`), or
    with `stop_ratio` x validation loss above the training loss (`paper`)."""
    budget = config.schedule
    if isinstance(budget, Converge):
        strike = not improved
    else:
        strike = budget.stop_ratio * val_loss > train_loss
    return state.strikes + 1 if strike else 0


def _stop_reason(state: _Progress, config: TrainConfig) -> tuple[str, str]:
    """(a protocols.StoppedBy, a sentence) once the protocol says stop, else ("", "")."""
    budget = config.schedule
    if isinstance(budget, Converge):
        if state.strikes >= budget.patience:
            return "patience", (
                f"validation loss did not improve for {budget.patience} checks "
                f"({budget.patience * budget.eval_every} steps)"
            )
        if state.steps >= budget.max_steps:
            return "budget", f"reached the budget of {budget.max_steps} steps"
        return "", ""
    if state.strikes >= budget.stop_patience:
        return "overfitting-rule", (
            f"{budget.stop_ratio} x validation loss exceeded the training loss "
            f"{budget.stop_patience} epochs in a row"
        )
    if state.epoch >= budget.max_epochs:
        return "epoch-cap", f"reached max_epochs={budget.max_epochs}"
    return "", ""


def _bar_total(config: TrainConfig, n_train: int) -> int:
    """The progress bar counts gradient steps, up to the budget or the epoch cap."""
    budget = config.schedule
    if isinstance(budget, Converge):
        return budget.max_steps
    return budget.max_epochs * batches_per_epoch(n_train, config.batch_size)


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
    # a larger budget continues a finished run, except under cosine, whose learning rate at
    # every step depends on the budget
    budgets = ("max_epochs",) if config.protocol == "cosine" else ("max_epochs", "max_steps")
    cfg = {k: v for k, v in config.to_dict().items() if k not in budgets}
    return {
        "model": entry.name,
        "model version": entry.version,
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
    state.stopped_by, state.stopped = _stop_reason(state, config)  # a larger budget continues
    trainer.load_params(groups["params"])
    trainer.load_optimizer_state(groups["optimizer"])
    return state, groups["best"]


def _progress_bar(config: TrainConfig, entry: ModelEntry) -> Progress:
    return Progress(
        TextColumn("{task.fields[name]}"),
        BarColumn(),
        MofNCompleteColumn(),
        TextColumn("steps"),
        TextColumn("{task.fields[loss]}"),
        TimeElapsedColumn(),
        TextColumn("at most"),
        TimeRemainingColumn(),  # from the budget: early stopping only shortens it
        disable=not config.progress,
        transient=False,
    )

"""A training's checkpoint folder: what is saved after every epoch, and what a resumed run
may trust.

    resume.safetensors           the last epoch: parameters, optimizer state, the best
                                 parameters so far, and (as metadata) identity and progress
    resume.previous.safetensors  the epoch before, kept as the fallback
    best/                        the best model as a `TrainedModel` folder, for users

Every file carries its content hash (`checkpoints`). A resume checkpoint that fails its
check is deleted with a warning and the run falls back to the previous one, or to scratch;
since the batch order of an epoch depends on (seed, epoch) only, the result is the same as
an uninterrupted run's. The resume checkpoint holds the best parameters itself, so a
damaged `best/` is rewritten from it instead of costing a retraining.
"""

from __future__ import annotations

import os
import warnings
from pathlib import Path
from typing import Any

import numpy as np

from symbench.core.training.checkpoints import (
    CheckpointError,
    checkpoint_sha256,
    read_tensors,
    write_tensors,
)
from symbench.core.training.trained_model import TENSORS, TrainedModel

RESUME = "resume.safetensors"
PREVIOUS = "resume.previous.safetensors"
BEST_DIR = "best"
GROUPS = ("params", "optimizer", "best")  # the arrays of a resume checkpoint, by prefix

Arrays = dict[str, np.ndarray]


class CheckpointWarning(UserWarning):
    """A damaged checkpoint was found and set aside; the run recovers without it."""


def save(
    folder: Path, groups: dict[str, Arrays], metadata: dict[str, Any], best: TrainedModel | None
) -> None:
    """One epoch's resume checkpoint (the last one becomes the previous); `best` too when
    given. `best/` is written first: a crash in between leaves an older resume checkpoint,
    which retrains into the same best model."""
    if best is not None:
        best.save(folder / BEST_DIR)
    arrays = {f"{group}/{k}": v for group in GROUPS for k, v in groups[group].items()}
    if (folder / RESUME).is_file():
        os.replace(folder / RESUME, folder / PREVIOUS)
    write_tensors(folder / RESUME, arrays, metadata)


def load(folder: Path) -> tuple[dict[str, Arrays], Any] | None:
    """The newest resume checkpoint that passes its hash check, as (arrays by group,
    metadata); None when there is none. Each damaged one is deleted with a warning."""
    found = [folder / name for name in (RESUME, PREVIOUS) if (folder / name).is_file()]
    for i, path in enumerate(found):
        try:
            arrays, metadata = read_tensors(path)
        except CheckpointError as exc:
            path.unlink()
            fallback = found[i + 1 :]
            then = f"falling back to {fallback[0]}" if fallback else "training from scratch"
            warnings.warn(f"{exc}; deleted it, {then}", CheckpointWarning, stacklevel=3)
            continue
        return {group: _group(arrays, group) for group in GROUPS}, metadata
    return None


def _group(arrays: Arrays, group: str) -> Arrays:
    prefix = f"{group}/"
    return {k.removeprefix(prefix): v for k, v in arrays.items() if k.startswith(prefix)}


def check_best(folder: Path, model: TrainedModel) -> None:
    """Rewrite `best/` from the resume checkpoint's `model` when it is damaged or missing."""
    try:
        checkpoint_sha256(folder / BEST_DIR / TENSORS)
    except CheckpointError as exc:
        warnings.warn(
            f"{exc}; rewriting it from the resume checkpoint", CheckpointWarning, stacklevel=3
        )
        model.save(folder / BEST_DIR)

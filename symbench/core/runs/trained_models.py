"""The models a run trained, asked for by its record (its run key) under the output folder
the run wrote: where the checkpoints lie (`checkpoint_root`, the `best` folder of each
training) stays the runs layer's business, so readers such as the site's clips never
spell the layout."""

from __future__ import annotations

from dataclasses import dataclass, replace
from pathlib import Path
from typing import TYPE_CHECKING

from symbench.core.common.errors import SymbenchError
from symbench.core.runs.results import RecordV1
from symbench.core.runs.spec import checkpoint_root

if TYPE_CHECKING:
    from symbench.core.training.trained_model import TrainedModel


class TrainedModelNotFound(SymbenchError):
    """No finished training (`found` empty), or several (`found`), at `where` (a pattern)."""

    def __init__(self, where: Path, found: list[Path]):
        self.where, self.found = where, found
        what = ", ".join(map(str, found)) if found else "nothing"
        super().__init__(f"{what} at {where}")


@dataclass(frozen=True)
class StoredModel:
    """A training a run left under its output folder: found by `trained_model`, loaded by
    `load` (never retrained)."""

    folder: Path
    record: RecordV1
    variant: str

    def load(self) -> TrainedModel:
        """The model, with the run's architecture on the training's input variant; an error
        when the training did not finish."""
        from symbench.core.plugin import registry
        from symbench.core.training.trained_model import TrainedModel

        model = self.record.model
        entry = replace(registry.model(model.name, model.backend), variant=self.variant)
        loaded = TrainedModel.load(self.folder, entry)
        if not loaded.stopped:
            raise SymbenchError(
                f"{self.folder} is not a finished training; run {self.record.key()} again"
            )
        return loaded


def trained_model(
    output: Path, record: RecordV1, split: str, variant: str, dataset: str | None = None
) -> StoredModel:
    """The model that the run of `record` trained on `split` and `variant` under `output`
    (its results folder), on `dataset` when it was retrained on another dataset than the
    run's (the closed loop's noisy data); `TrainedModelNotFound` when there is none, or more
    than one."""
    from symbench.core.training.resume import BEST_DIR
    from symbench.core.training.trained_model import TENSORS

    # retrained on another dataset it lies in that dataset's folder under the run's key; on
    # another split of the run's own, under the key of the run that trains it as its own
    on = f"{dataset}-*/" if dataset is not None and dataset != record.dataset.id else ""
    key = record.key() if on else record.key(split, variant)
    run = checkpoint_root(output, key, record.dataset.content_hash)
    pattern = f"{on}{split}__{variant}"
    found = sorted(f / BEST_DIR for f in run.glob(pattern) if (f / BEST_DIR / TENSORS).is_file())
    if len(found) != 1:
        raise TrainedModelNotFound(run / pattern / BEST_DIR, found)
    return StoredModel(found[0], record, variant)

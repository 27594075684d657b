"""The same architecture's test error on each standard split, side by side.

Not all or nothing: a split the dataset cannot make (an imported log without headings has no
`unseen-heading`, one with a single yaw sector no `unseen-rotation`) is named with the reason
under `skipped_splits`, and the others are still trained and reported (`splits`)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from symbench import SymbenchError
from symbench.plugins.evaluators.torque_error import split_metrics

if TYPE_CHECKING:  # symbench's names load the data stack: when a run evaluates, not with the CLI
    from symbench import EvaluationContext

NAME = "generalization"
DESCRIPTION = (
    "test RMSE on iid, unseen-heading and unseen-rotation (retrains per split; a split the "
    "dataset cannot make is named and skipped)"
)
SPLITS = ("iid", "unseen-heading", "unseen-rotation")


def trainings(context: EvaluationContext) -> list[tuple[str | None, str, str]]:
    """The splits `evaluate` trains on (those the dataset can make), for a run to train
    ahead."""
    return [(None, split, context.entry.variant) for split in SPLITS if _makeable(context, split)]


def _makeable(context: EvaluationContext, split: str) -> bool:
    try:  # labelling trajectories is cheap
        context.dataset.split_indices(split, context.seed)
    except SymbenchError:
        return False
    return True


def evaluate(context: EvaluationContext) -> dict:
    out: dict = {}
    trained, skipped = [], {}
    for split in SPLITS:
        try:  # labelling trajectories is cheap: find out before training
            context.dataset.split_indices(split, context.seed)
        except SymbenchError as exc:
            skipped[split] = str(exc).splitlines()[0] if str(exc) else type(exc).__name__
            continue
        metrics = split_metrics(context.on_split(split))
        out[f"rmse_{split}"] = metrics["rmse"]
        out[f"nrmse_{split}"] = metrics["nrmse"]
        trained.append(split)
    if not trained:  # nothing to compare: the run's table shows why
        reasons = "; ".join(f"{split}: {why}" for split, why in skipped.items())
        return {"skipped": f"no standard split can be made ({reasons})", "skipped_splits": skipped}
    return {**out, "splits": trained, "skipped_splits": skipped}

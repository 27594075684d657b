"""A generalization split's error read against its size-matched iid control.

A split that holds out a region (unseen rotations, headings, slopes, a gait) also trains on
fewer climbs than `iid`, so its error alone mixes the two: dataset v6's `unseen-rotation`
trained on 7 climbs where `iid` trained on 65. The control (`control_of(split)`) trains on
as many climbs drawn at random from the iid pool, with the same seed and a test set of the
same size, so `gap` = the split's test RMSE / the control's is the price of the held-out
region alone: about 1 for a model the region is no news to, above 1 for one that must
extrapolate. On a split without a control (iid, the fractions, the controls themselves)
it reports nothing and says so.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from symbench.plugins.evaluators.torque_error import split_metrics

if TYPE_CHECKING:  # symbench's names load the data stack: when a run evaluates, not with the CLI
    from symbench import EvaluationContext

NAME = "generalization-gap"
DESCRIPTION = (
    "the split's test RMSE over its size-matched iid control's (retrains on the control "
    "split: same training size, seed and test-set size)"
)


def trainings(context: EvaluationContext) -> list[tuple[str | None, str, str]]:
    """The control split, for a run to train ahead."""
    from symbench import control_of

    control = control_of(context.split)
    return [] if control is None else [(None, control, context.entry.variant)]


def evaluate(context: EvaluationContext) -> dict[str, Any]:
    from symbench import control_of

    control = control_of(context.split)
    if control is None:
        return {"skipped": f"split {context.split} has no size-matched control"}
    own = split_metrics(context.on_split(context.split))
    matched = split_metrics(context.on_split(control))
    return {
        "control": control,
        "rmse": own["rmse"],
        "control_rmse": matched["rmse"],
        "gap": own["rmse"] / matched["rmse"],
    }

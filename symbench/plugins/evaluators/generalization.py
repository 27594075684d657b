"""The same architecture's test error on each standard split, side by side."""

from __future__ import annotations

from symbench import EvaluationContext
from symbench.plugins.evaluators.torque_error import split_metrics

NAME = "generalization"
DESCRIPTION = "test RMSE on iid, unseen-heading and unseen-rotation (retrains per split)"
SPLITS = ("iid", "unseen-heading", "unseen-rotation")


def evaluate(context: EvaluationContext) -> dict:
    out = {}
    for split in SPLITS:
        metrics = split_metrics(context.on_split(split))
        out[f"rmse_{split}"] = metrics["rmse"]
        out[f"nrmse_{split}"] = metrics["nrmse"]
    return out

"""Test torque RMSE, overall and per joint type, and normalized by the targets' spread."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:  # symbench's names load the data stack: when a run evaluates, not with the CLI
    from symbench import EvaluationContext, TrainedOnSplit

NAME = "torque-error"
DESCRIPTION = "test torque RMSE (N m) overall and per joint type; NRMSE = RMSE / target std"


def torque_metrics(pred: np.ndarray, target: np.ndarray) -> dict[str, float]:
    from symbench import rmse, schema

    per_joint = rmse(pred, target, axis=(0, 1))
    overall = float(rmse(pred, target))
    return {
        "rmse": overall,
        **{f"rmse_{j}": float(v) for j, v in zip(schema.JOINTS, per_joint)},
        "nrmse": overall / spread if (spread := float(np.std(target))) > 0 else float("nan"),
        "samples": int(len(target)),
    }


def split_metrics(trained: TrainedOnSplit) -> dict[str, float]:
    """Torque metrics of a model trained on some split, on that split's test set."""
    return torque_metrics(trained.predict(trained.test.inputs), trained.test.target)


def evaluate(context: EvaluationContext) -> dict[str, float]:
    return torque_metrics(context.predictions(), context.test.target)

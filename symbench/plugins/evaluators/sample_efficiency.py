"""Test error against the fraction of training trajectories, with a plot per robot."""

from __future__ import annotations

from symbench import EvaluationContext, sample_efficiency_png
from symbench.plugins.evaluators.torque_error import split_metrics

NAME = "sample-efficiency"
DESCRIPTION = "test RMSE after training on 10, 25, 50, 75 and 100 % of the training trajectories"
FRACTIONS = (0.1, 0.25, 0.5, 0.75)


def evaluate(context: EvaluationContext) -> dict:
    curve = {}
    for f in FRACTIONS:
        curve[str(f)] = split_metrics(context.on_split(f"fraction-{f}"))["rmse"]
    curve["1.0"] = split_metrics(context.on_split("iid"))["rmse"]
    plot = context.output_dir / f"{context.robot.name}-{context.entry.name}-sample-efficiency.png"
    label = f"{context.entry.name} ({context.entry.backend})"
    x = [float(f) for f in curve]
    sample_efficiency_png(
        {label: (x, list(curve.values()), None)}, f"{context.robot.name}: sample efficiency", plot
    )
    return {"rmse_by_fraction": curve, "plot": str(plot)}

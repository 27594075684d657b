"""Test error against the fraction of training trajectories, with a plot per robot."""

from __future__ import annotations

from symbench import EvaluationContext, sample_efficiency_png
from symbench.plugins.evaluators.torque_error import split_metrics

NAME = "sample-efficiency"
DESCRIPTION = (
    "test RMSE after training on the preset's fractions (fraction-F splits) and on all "
    "(iid) of the training trajectories"
)


def evaluate(context: EvaluationContext) -> dict:
    curve = {}
    for f in context.preset.sample_efficiency.fractions:
        curve[str(f)] = split_metrics(context.on_split(f"fraction-{f:g}"))["rmse"]
    curve["1.0"] = split_metrics(context.on_split("iid"))["rmse"]
    e = context.entry  # one plot per run: named like its record, so no run overwrites another's
    run = f"{context.dataset.id}__{context.preset.name}__{e.name}__{e.variant}__{e.backend}"
    plot = context.output_dir / f"{run}__seed{context.seed}-sample-efficiency.png"
    label = f"{context.entry.name} ({context.entry.backend})"
    x = [float(f) for f in curve]
    sample_efficiency_png(
        {label: (x, list(curve.values()), None)}, f"{context.robot.name}: sample efficiency", plot
    )
    return {"rmse_by_fraction": curve, "plot": str(plot)}

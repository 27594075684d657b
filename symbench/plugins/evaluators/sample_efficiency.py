"""Test error against the fraction of training trajectories, with a plot per robot."""

from __future__ import annotations

from typing import TYPE_CHECKING

from symbench.plugins.evaluators.torque_error import split_metrics

if TYPE_CHECKING:  # symbench's names load the data stack: when a run evaluates, not with the CLI
    from symbench import EvaluationContext

NAME = "sample-efficiency"
DESCRIPTION = (
    "test RMSE after training on the preset's fractions (fraction-F splits) and on all "
    "(iid) of the training trajectories"
)


def _splits(context: EvaluationContext) -> list[str]:
    return [f"fraction-{f:g}" for f in context.preset.sample_efficiency.fractions] + ["iid"]


def trainings(context: EvaluationContext) -> list[tuple[str | None, str, str]]:
    """The splits `evaluate` trains on, for a run to train ahead."""
    return [(None, split, context.entry.variant) for split in _splits(context)]


def evaluate(context: EvaluationContext) -> dict:
    from symbench import sample_efficiency_png

    fractions = [str(f) for f in context.preset.sample_efficiency.fractions] + ["1.0"]
    curve = {
        f: split_metrics(context.on_split(split))["rmse"]
        for f, split in zip(fractions, _splits(context), strict=True)
    }
    e = context.entry  # one plot per run: named like its record, so no run overwrites another's
    run = f"{context.dataset.id}__{context.preset.name}__{e.name}__{e.variant}__{e.backend}"
    plot = context.output_dir / f"{run}__seed{context.seed}-sample-efficiency.png"
    label = f"{context.entry.name} ({context.entry.backend})"
    x = [float(f) for f in curve]
    sample_efficiency_png(
        {label: (x, list(curve.values()), None)}, f"{context.robot.name}: sample efficiency", plot
    )
    return {"rmse_by_fraction": curve, "plot": str(plot)}

"""Built-in evaluators, registered through the `symbench_evaluators` hook."""

from __future__ import annotations

import symbench
from symbench import EvaluatorEntry
from symbench.plugins.evaluators import (
    closed_loop,
    data_symmetry,
    equivariance,
    generalization,
    generalization_gap,
    image_overlap,
    invariance,
    sample_efficiency,
    torque_error,
)

MODULES = (
    torque_error,
    equivariance,
    invariance,
    generalization,
    sample_efficiency,
    closed_loop,
    data_symmetry,
    image_overlap,
    generalization_gap,
)
# What each needs from the dataset beyond its test samples (symbench.EVALUATOR_NEEDS); a run
# on a dataset without it skips the evaluator with the reason. The closed-loop evaluator
# simulates the held-out scenarios and drives the robot with the `next` variant.
NEEDS: dict[str, tuple[str, ...]] = {
    torque_error.NAME: (),
    equivariance.NAME: ("raw",),  # transforms raw test states
    invariance.NAME: ("raw",),
    generalization.NAME: (),  # trains on the standard splits it can, names the others
    sample_efficiency.NAME: (),
    closed_loop.NAME: ("simulator", "variant:next"),
    data_symmetry.NAME: ("raw", "scenarios"),  # pairs climbs by their scenarios
    image_overlap.NAME: ("raw",),  # compares raw states after relabelling
    generalization_gap.NAME: (),  # trains on the split's control
}


@symbench.hookimpl
def symbench_evaluators() -> list[EvaluatorEntry]:
    return [
        EvaluatorEntry(
            m.NAME,
            evaluate=m.evaluate,
            description=m.DESCRIPTION,
            needs=NEEDS[m.NAME],
            trainings=getattr(m, "trainings", None),  # those that train declare it
        )
        for m in MODULES
    ]

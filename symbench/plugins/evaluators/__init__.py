"""Built-in evaluators, registered through the `symbench_evaluators` hook."""

from __future__ import annotations

import symbench
from symbench import EvaluatorEntry
from symbench.plugins.evaluators import (
    closed_loop,
    equivariance,
    generalization,
    invariance,
    sample_efficiency,
    torque_error,
)

MODULES = (torque_error, equivariance, invariance, generalization, sample_efficiency, closed_loop)


@symbench.hookimpl
def symbench_evaluators() -> list[EvaluatorEntry]:
    return [EvaluatorEntry(m.NAME, evaluate=m.evaluate, description=m.DESCRIPTION) for m in MODULES]

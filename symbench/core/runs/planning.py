"""What a run's evaluators see (`EvaluationContext`) and the trainings they declare before
any runs, so a run can train them ahead and a sweep can make their datasets first."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any, NoReturn

import numpy as np

from symbench.core.common.arrays import ViewArrays
from symbench.core.common.errors import SymbenchError
from symbench.core.config.presets import preset
from symbench.core.data.dataset import Dataset
from symbench.core.plugin import registry
from symbench.core.runs.evaluation import EvaluationContext, TrainedOnSplit, skip_reason
from symbench.core.runs.spec import RunSpec, model_entry
from symbench.core.runs.trainings import TrainingJob


def evaluation_context(
    spec: RunSpec,
    dataset: Dataset,
    test: ViewArrays,
    predict: Callable[[dict[str, np.ndarray]], np.ndarray],
    retrain: Callable[[str, str], TrainedOnSplit],
    retrain_on: Callable[[str, str, str], TrainedOnSplit],
) -> EvaluationContext:
    """What the run's evaluators see: its model, preset, split and seed on `dataset`."""
    return EvaluationContext(
        entry=model_entry(spec),
        dataset=dataset,
        preset=preset(spec.preset),
        split=spec.split,
        seed=spec.seed,
        predict=predict,
        test=test,
        test_trajectories=dataset.split_indices(spec.split, spec.seed).test,
        output_dir=spec.output,
        retrain=retrain,
        retrain_on=retrain_on,
    )


def planned_trainings(context: EvaluationContext, names: tuple[str, ...]) -> list[TrainingJob]:
    """The trainings the run's evaluators say they will ask for (`EvaluatorEntry.trainings`),
    without repeats; the run's own training first."""
    jobs = [TrainingJob(None, context.split, context.entry.variant)]
    own = getattr(context.dataset, "id", None)
    for name in names:
        entry = registry.evaluator(name)
        if entry.trainings is None or skip_reason(entry, context.dataset) is not None:
            continue
        try:
            declared = [
                (did, str(split), str(variant)) for did, split, variant in entry.trainings(context)
            ]
        except SymbenchError as exc:
            raise SymbenchError(f"evaluator '{name}': {exc}") from exc
        except Exception as exc:  # a plugin's bug, named before any minute is spent
            raise SymbenchError(
                f"evaluator '{name}': trainings() failed: {type(exc).__name__}: {exc}"
            ) from exc
        for did, split, variant in declared:
            job = TrainingJob(None if did in (None, own) else did, split, variant)
            if job not in jobs:
                jobs.append(job)
    return jobs


def _not_while_planning(*_: object) -> NoReturn:
    raise SymbenchError("trainings() may declare trainings, not run them")


class _TestSamplesWhilePlanning:
    """The context's `test` while a sweep plans: its samples are not made yet (building a
    view of a `paper` dataset costs tens of seconds, once per run, not per planned run)."""

    def __getattr__(self, name: str) -> Any:
        raise SymbenchError(
            "trainings() runs while a sweep plans, before the test samples are made: "
            "declare trainings from the context's split, preset and dataset"
        )


def declared_datasets(spec: RunSpec, dataset: Dataset) -> list[str]:
    """The other datasets the run's evaluators declare trainings on (the closed loop's noisy
    variant), so that a sweep makes each once before runs that need it start side by side."""
    planning = _not_while_planning
    test: Any = _TestSamplesWhilePlanning()  # stands in for the ViewArrays not made yet
    context = evaluation_context(spec, dataset, test, planning, planning, planning)
    jobs = planned_trainings(context, spec.evaluators)
    return [job.dataset for job in jobs if job.dataset is not None]

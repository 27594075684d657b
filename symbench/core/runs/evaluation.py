"""What an evaluator receives, and running the chosen evaluators one by one.

Evaluators see a trained model only through `predict`, so PyTorch and JAX models are judged
by the same code. Evaluators that transform test scenes (equivariance, invariance) work on
raw states and recompute the model's own view, so every representation gets the same test.
"""

from __future__ import annotations

import json
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from symbench.core.common.arrays import ViewArrays
from symbench.core.common.errors import SymbenchError
from symbench.core.data.presets import Preset
from symbench.core.plugin.entries import ModelEntry
from symbench.core.plugin.registry import evaluator

Predict = Callable[[dict[str, np.ndarray]], np.ndarray]


@dataclass(frozen=True)
class TrainedOnSplit:
    """A model of the same architecture trained on some split and variant, with its test set."""

    split: str
    variant: str
    predict: Predict
    test: ViewArrays


@dataclass
class EvaluationContext:
    """Everything an evaluator may use.

    `retrain(split, variant)` trains the same architecture on another split or input variant
    (the closed-loop evaluator needs the `next` variant); results are cached per pair.
    `preset` holds the run's budgets and horizons (test samples, closed-loop horizon, ...).
    """

    entry: ModelEntry
    dataset: Any  # symbench.core.data.dataset.Dataset
    preset: Preset
    split: str
    seed: int
    predict: Predict
    test: ViewArrays
    test_trajectories: np.ndarray
    output_dir: Path
    retrain: Callable[[str, str], TrainedOnSplit]
    _trained: dict[tuple[str, str], TrainedOnSplit] = field(default_factory=dict, repr=False)

    @property
    def robot(self):
        return self.dataset.spec

    def predictions(self) -> np.ndarray:
        return self.predict(self.test.inputs)

    def on_split(self, split: str, variant: str | None = None) -> TrainedOnSplit:
        """This run's model for its own split and variant; a retrained one (cached) otherwise."""
        variant = variant or self.entry.variant
        if (split, variant) == (self.split, self.entry.variant):
            return TrainedOnSplit(split, variant, self.predict, self.test)
        if (split, variant) not in self._trained:
            self._trained[split, variant] = self.retrain(split, variant)
        return self._trained[split, variant]

    def test_raw(self) -> tuple[dict[str, np.ndarray], np.ndarray]:
        """Raw columns of the test trajectories (whole trajectories, up to the preset's
        `evaluation.max_samples` rows)."""
        raw, ids = self.dataset.raw()
        cap = self.preset.evaluation.max_samples
        keep = np.flatnonzero(np.isin(ids, self.test_trajectories))[:cap]
        return {k: v[keep] for k, v in raw.items()}, ids[keep]

    def predict_raw(self, raw: dict[str, np.ndarray], ids: np.ndarray) -> np.ndarray:
        """The model's torques for raw states, through its own view."""
        from symbench.core.data.views import build_view

        arrays = build_view(raw, ids, self.dataset.frames, self.entry.view, self.entry.variant)
        return self.predict(arrays.inputs)


def rmse(pred: np.ndarray, target: np.ndarray, axis: Any = None) -> np.ndarray:
    return np.sqrt(np.mean((np.asarray(pred) - np.asarray(target)) ** 2, axis=axis))


def relative_error(actual: np.ndarray, expected: np.ndarray) -> float:
    """max |actual - expected| / max |expected|: how far two torque predictions differ,
    relative to their size (the equivariance kit and the evaluators share it)."""
    actual, expected = np.asarray(actual), np.asarray(expected)
    scale = float(np.max(np.abs(expected))) if expected.size else 0.0
    return float(np.max(np.abs(actual - expected))) / max(scale, np.finfo(np.float64).tiny)


def run_evaluators(
    names: list[str],
    context: EvaluationContext,
    progress: Callable[[str], None] = lambda name: None,
) -> dict[str, dict]:
    """Each evaluator's metrics; one that raises, or returns anything but a JSON-ready
    mapping of metric names, is named in the error."""
    results: dict[str, dict] = {}
    for name in names:
        entry = evaluator(name)
        progress(name)
        try:
            metrics = entry.evaluate(context)
        except SymbenchError:
            raise
        except Exception as exc:
            raise SymbenchError(f"evaluator '{name}' failed: {type(exc).__name__}: {exc}") from exc
        results[name] = checked_metrics(name, metrics)
    return results


def checked_metrics(name: str, metrics: Any) -> dict[str, Any]:
    """`metrics` as a dict, or an error naming the evaluator: the record stores it as JSON."""
    if not isinstance(metrics, Mapping) or not all(isinstance(k, str) for k in metrics):
        raise SymbenchError(
            f"evaluator '{name}' returned {type(metrics).__name__}, expected a "
            "mapping of metric names (str) to values"
        )
    try:
        json.dumps(dict(metrics))
    except (TypeError, ValueError) as exc:
        raise SymbenchError(
            f"evaluator '{name}' returned a value that is not JSON: {exc}"
        ) from None
    return dict(metrics)

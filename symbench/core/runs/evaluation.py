"""What an evaluator receives, and running the chosen evaluators one by one.

Evaluators see a trained model only through `predict`, so PyTorch and JAX models are judged
by the same code. Evaluators that transform test scenes (equivariance, invariance) work on
raw states and recompute the model's own view, so every representation gets the same test.

An evaluator declares what it needs from the dataset (`EvaluatorEntry.needs`); a dataset
provides what it holds (a generated one everything; an imported one no simulator replay when
its scenarios are incomplete, ...). An evaluator whose needs are not met is skipped: its
metrics are `{"skipped": "<one-line reason>"}`, shown in the run's table and kept in the
record, and the run goes on.
"""

from __future__ import annotations

import json
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from symbench.core.common.arrays import ViewArrays
from symbench.core.common.errors import SymbenchError
from symbench.core.config.presets import RECORD_PERIOD, Preset, dataset_id, parse_dataset_id, preset
from symbench.core.data.storage.scenario_fields import SCENARIO_KEYS
from symbench.core.plugin.entries import EvaluatorEntry, ModelEntry
from symbench.core.plugin.registry import evaluator
from symbench.core.runs.timing import RETRAINING_KEY, Timer, evaluator_key

if TYPE_CHECKING:  # the data layer's types, for annotations only
    from symbench.core.data.dataset import Dataset
    from symbench.core.data.symmetry.overlap import SplitOverlap
    from symbench.core.robot.specs import RobotSpec

Predict = Callable[[dict[str, np.ndarray]], np.ndarray]

SKIPPED = "skipped"  # the one metric of a skipped evaluator: why it could not run
# what each need reads as in a skip reason ("needs a simulator replay: ...")
NEED_TEXT = {
    "simulator": "a simulator replay",
    "scenarios": "complete scenarios",
    "variant:next": f"the next variant at the {RECORD_PERIOD * 1000:g} ms record period",
    "raw": "raw base and joint states",
    "contact": "known contact flags",
}
PERIOD_TOLERANCE = 0.05  # relative: a record period this close to RECORD_PERIOD is the same
# The scenario fields that make a scenario complete, enough for a simulator replay (a
# missing leg order means the default one, a missing torque noise or gait spread none).
REPLAY_FIELDS = tuple(
    k for k in SCENARIO_KEYS if k not in ("leg_order", "torque_noise", "gait_spread")
)
RAW_COLUMNS = ("base_pos", "base_quat", "base_linvel", "base_angvel", "base_linacc", "q", "qd")


@dataclass(frozen=True)
class TrainedOnSplit:
    """A model of the same architecture trained on some split and variant, with its test set
    and, for a retrained one, which network it is (`provenance`: its data's id and content
    hash, its checkpoint's hash, steps and why training stopped; empty for the run's own
    model, which the record's `training` section describes)."""

    split: str
    variant: str
    predict: Predict
    test: ViewArrays
    provenance: Mapping[str, Any] = field(default_factory=dict)


@dataclass
class EvaluationContext:
    """Everything an evaluator may use.

    `retrain(split, variant)` trains the same architecture on another split or input variant
    (the closed-loop evaluator needs the `next` variant); results are cached per pair.
    `retrain_on(dataset_id, split, variant)` does the same on another dataset of the robot
    (the closed loop's data for control, `control_dataset`), with the same split, seed and
    training configuration, never on this run's test trajectories; None: not offered.
    `preset` holds the run's budgets and horizons (test samples, closed-loop horizon, ...).
    """

    entry: ModelEntry
    dataset: Dataset
    preset: Preset
    split: str
    seed: int
    predict: Predict
    test: ViewArrays
    test_trajectories: np.ndarray
    output_dir: Path
    retrain: Callable[[str, str], TrainedOnSplit]
    retrain_on: Callable[[str, str, str], TrainedOnSplit] | None = None
    _trained: dict[tuple[str, str], TrainedOnSplit] = field(default_factory=dict, repr=False)
    _trained_on: dict[tuple[str, str, str], TrainedOnSplit] = field(
        default_factory=dict, repr=False
    )

    @property
    def robot(self) -> RobotSpec:
        """The robot of the run's dataset (its registered spec, checked against the data)."""
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

    def control_dataset(self) -> str | None:
        """The dataset a controller is trained on: for a standard dataset whose preset names
        one (`ClosedLoop.train_preset`), that preset's dataset of the robot (its noisy
        variant: the expert's execution perturbed, its commands as labels); else this run's
        own dataset (None when it has no id)."""
        did = getattr(self.dataset, "id", None)
        parsed = parse_dataset_id(did) if isinstance(did, str) else None
        if parsed is None or self.retrain_on is None or dataset_id(*parsed) != did:
            return did
        train = preset(parsed[1]).closed_loop.train_preset
        return dataset_id(parsed[0], train) if train else did

    def on_dataset(self, dataset: str | None, split: str, variant: str) -> TrainedOnSplit:
        """A model of this architecture trained on `dataset` (its `split`, this run's seed),
        cached; this run's own dataset (or None) is `on_split`."""
        if dataset is None or dataset == getattr(self.dataset, "id", None):
            return self.on_split(split, variant)
        if self.retrain_on is None:
            raise SymbenchError(f"this run cannot train on another dataset ('{dataset}')")
        if (dataset, split, variant) not in self._trained_on:
            self._trained_on[dataset, split, variant] = self.retrain_on(dataset, split, variant)
        return self._trained_on[dataset, split, variant]

    def image_overlap(self) -> SplitOverlap:
        """The image overlap of the run's split and seed (`symbench.split_overlap`): not a
        property of the model, so the runs of one output folder measure it once."""
        from symbench.core.runs.overlap_cache import cached_split_overlap

        return cached_split_overlap(self.dataset, self.split, self.seed, self.output_dir)

    def test_raw(self) -> tuple[dict[str, np.ndarray], np.ndarray]:
        """Raw columns of the test trajectories (whole trajectories, up to the preset's
        `evaluation.max_samples` rows)."""
        raw, ids = self.dataset.raw()
        cap = self.preset.evaluation.max_samples
        keep = np.flatnonzero(np.isin(ids, self.test_trajectories))[:cap]
        return {k: v[keep] for k, v in raw.items()}, ids[keep]

    def predict_raw(self, raw: dict[str, np.ndarray], ids: np.ndarray) -> np.ndarray:
        """The model's torques for raw states, through its own view."""
        from symbench.core.data.views.transforms import build_view

        arrays = build_view(raw, ids, self.dataset.frames, self.entry.view, self.entry.variant)
        return self.predict(arrays.inputs)


def _missing_fields(dataset: Dataset, fields: tuple[str, ...]) -> list[str]:
    scenarios = dataset.scenarios
    return [f for f in fields if any(s.get(f) is None for s in scenarios)]


def _imported(dataset: Dataset) -> str:
    return f"dataset '{dataset.id}' is imported"


def unmet_need(need: str, dataset: Dataset) -> str | None:
    """Why `dataset` does not provide `need` (one line), or None when it does. A generated
    dataset provides everything; an imported one what its metadata and scenarios hold."""
    meta = dataset.metadata
    if need == "variant:next":
        period = float(meta["record_period_s"])
        if abs(period - RECORD_PERIOD) > PERIOD_TOLERANCE * RECORD_PERIOD:
            return (
                f"dataset '{dataset.id}' is recorded every {period * 1000:g} ms, so its next "
                f"state is not the one {RECORD_PERIOD * 1000:g} ms ahead"
            )
        return None
    unknown = set(meta.get("unknown_columns") or ())
    if need in ("raw", "contact"):
        columns = RAW_COLUMNS if need == "raw" else ("contact",)
        declared = [c for c in columns if c in unknown]
        if declared:
            return f"dataset '{dataset.id}' declares {', '.join(declared)} unknown"
        return None
    if meta.get("source") == "generated":
        return None
    if need == "scenarios":
        missing = _missing_fields(dataset, REPLAY_FIELDS)
        if missing:
            return f"{_imported(dataset)} and its scenarios lack {', '.join(missing)}"
        return None
    if need == "simulator":
        missing = _missing_fields(dataset, REPLAY_FIELDS)
        if missing:
            return f"{_imported(dataset)} and its scenarios lack {', '.join(missing)}"
        try:
            _ = dataset.spec  # the registered robot, the very spec the logs were imported for
        except SymbenchError as exc:
            return f"{_imported(dataset)}: {exc}"
        return None
    raise SymbenchError(f"unknown evaluator need '{need}'")


def skip_reason(entry: EvaluatorEntry, dataset: Dataset) -> str | None:
    """The one-line reason why `entry` cannot run on `dataset` (its first unmet need), or
    None when it can."""
    for need in entry.needs:
        why = unmet_need(need, dataset)
        if why is not None:
            return f"needs {NEED_TEXT[need]}: {why}"
    return None


def run_evaluators(
    names: list[str],
    context: EvaluationContext,
    timer: Timer,
    progress: Callable[[str], None] = lambda name: None,
) -> dict[str, dict[str, Any]]:
    """Each evaluator's metrics; one whose needs the dataset does not meet is skipped
    (`{"skipped": reason}`); one that raises, or returns anything but a JSON-ready mapping
    of metric names, is named in the error. Each evaluator's own wall seconds, less the
    retrainings it asked for, go into `timer` under `timing.evaluator_key`."""
    results: dict[str, dict[str, Any]] = {}
    for name in names:
        entry = evaluator(name)
        reason = skip_reason(entry, context.dataset)
        if reason is not None:  # shown by the run's table, kept in the record
            results[name] = {SKIPPED: reason}
            continue
        progress(name)
        try:
            metrics = timer.measure(
                evaluator_key(name), entry.evaluate, context, less=RETRAINING_KEY
            )
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

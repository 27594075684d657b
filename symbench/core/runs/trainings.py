"""The trainings of one run: its own and those its evaluators ask for, each into the run's
checkpoint folder (so an interrupted run resumes), trained ahead in parallel when the run has
more than one worker, announced and timed."""

from __future__ import annotations

import time
from collections.abc import Callable
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np
from filelock import FileLock

from symbench.core.common.arrays import ViewArrays
from symbench.core.common.errors import SymbenchError
from symbench.core.common.processes import WorkerDied, run_each
from symbench.core.data.dataset import Dataset
from symbench.core.data.splits import SplitIndices
from symbench.core.runs.evaluation import TrainedOnSplit
from symbench.core.runs.run_config import train_config
from symbench.core.runs.spec import RunSpec, checkpoint_root, ensure_dataset, model_entry
from symbench.core.runs.timing import RETRAINING_KEY, Timer
from symbench.core.training.loop import train
from symbench.core.training.trained_model import TrainedModel

Sets = tuple[ViewArrays, ViewArrays, ViewArrays]  # (train, val, test) samples of a split


@dataclass(frozen=True)
class TrainingJob:
    """One training a run needs: on dataset `dataset` (None: the run's own), its `split` and
    input `variant`, with the run's seed and configuration."""

    dataset: str | None
    split: str
    variant: str


def fit(
    spec: RunSpec, dataset: Dataset, job: TrainingJob, sets: Sets | None = None
) -> tuple[TrainedModel, SplitIndices, Sets, Dataset]:
    """Trains `job` into the run's checkpoint folder, or loads it when a finished training is
    there (`train_ahead` made it, or an earlier, interrupted run): (model, the split's
    trajectory ids, its (train, val, test) views, the dataset trained on). On another dataset
    (a noisy variant for control) the run's test trajectories are left out of training and
    validation (same grid: same ids). `sets`: the views of a split of the run's own dataset,
    when already made."""
    entry = replace(model_entry(spec), variant=job.variant)
    other = dataset
    if job.dataset is None or job.dataset == dataset.id:
        parts = dataset.split_indices(job.split, spec.seed)
        if sets is None:
            sets = dataset.split_views(entry.view, job.variant, job.split, spec.seed)
        shared = checkpoint_root(
            spec.output, spec.key(job.split, job.variant), dataset.content_hash
        )
        folder = shared / f"{job.split}__{job.variant}"
    else:
        other = ensure_dataset(replace(spec, dataset=job.dataset))
        held_out = dataset.split_indices(spec.split, spec.seed).test
        parts = other.split_indices(job.split, spec.seed)
        ids = (np.setdiff1d(parts.train, held_out), np.setdiff1d(parts.val, held_out), parts.test)
        arrays = other.view(entry.view, job.variant)
        train_set, val_set, test_set = (arrays.take(np.isin(arrays.trajectory, i)) for i in ids)
        sets = (train_set, val_set, test_set)
        root = checkpoint_root(spec.output, spec.key(), dataset.content_hash)
        folder = root / f"{other.id}-{other.content_hash[:12]}" / f"{job.split}__{job.variant}"
    folder.parent.mkdir(parents=True, exist_ok=True)
    # runs in parallel may ask for the same shared training: one trains, the other then
    # finds it finished and loads it
    with FileLock(folder.parent / f"{folder.name}.lock"):
        model = train(entry, sets[0], sets[1], train_config(spec), checkpoint_dir=folder)
    return model, parts, sets, other


def provenance(model: TrainedModel, data: Dataset, job: TrainingJob, seed: int) -> dict[str, Any]:
    """Which network a retraining made, for the metrics of the evaluator that judges it
    (the record's own `training` section describes only the run's model): its data, its
    checkpoint's content hash (`TrainedModel.sha256`, what its `model.safetensors` carries)
    and how its training ended."""
    return {
        "dataset": data.id,
        "dataset_content_hash": data.content_hash,
        "split": job.split,
        "variant": job.variant,
        "seed": seed,
        "checkpoint_sha256": model.sha256(),
        "steps": model.steps,
        "best_step": model.best_step,
        "stopped_by": model.stopped_by,
        "stop_reason": model.stopped,
        "best_val_loss": float(min(model.history["val_loss"])),
    }


def _fit_in_worker(item: tuple[RunSpec, TrainingJob]) -> tuple[TrainingJob, float]:
    spec, job = item
    start = time.perf_counter()
    fit(spec, ensure_dataset(spec), job)
    return job, time.perf_counter() - start


def train_ahead(
    spec: RunSpec, jobs: list[TrainingJob], on_done: Callable[[TrainingJob], None]
) -> dict[TrainingJob, float]:
    """Trains `jobs` in `spec.workers` processes at once, each into the run's checkpoint
    folder, where `fit` then finds it finished; returns each job's own seconds. Each process
    trains on one thread, as the run itself does, so a model is the same bit for bit
    whichever process trained it."""
    seconds: dict[TrainingJob, float] = {}

    def done(result: tuple[TrainingJob, float]) -> None:
        seconds[result[0]] = result[1]
        on_done(result[0])

    quiet = replace(spec, progress=False, workers=1)
    try:
        run_each(_fit_in_worker, [(quiet, job) for job in jobs], spec.workers, done, one_each=True)
    except WorkerDied as exc:
        raise SymbenchError(
            f"a worker process died training {len(exc.items)} model(s), even alone (out of "
            "memory?); the others are trained; run the same command again to retry"
        ) from None
    return seconds


@dataclass
class RunTrainings:
    """One run's trainings as its evaluators ask for them (`retrain`, `retrain_on`): `jobs`
    planned up front, the run's own first; each announced through `on_stage` and timed."""

    spec: RunSpec
    dataset: Dataset
    timer: Timer
    on_stage: Callable[[str], None]
    jobs: list[TrainingJob] = field(default_factory=list)
    ahead: dict[TrainingJob, float] = field(default_factory=dict)  # seconds, by job
    model: TrainedModel | None = None  # the run's own, once trained

    def predict(self, inputs: dict[str, np.ndarray]) -> np.ndarray:
        """The run's own model's torques (what its evaluators judge)."""
        assert self.model is not None, "the run's model is not trained yet"
        return self.model.predict(inputs)

    def announce(self, job: TrainingJob) -> None:
        """Says whether the stage trains, or loads what `train_ahead` trained."""
        verb = "loading the model trained ahead" if job in self.ahead else "training"
        target = f"{job.dataset} {job.split}" if job.dataset else job.split
        own = job == self.jobs[0]
        self.on_stage(verb if own else f"{verb} on {target} ({job.variant} variant)")

    def trained(self, job: TrainingJob) -> None:
        """Says a training made ahead has finished."""
        where = job.dataset or self.dataset.id
        self.on_stage(f"trained on {where} {job.split} ({job.variant} variant)")

    def train_ahead(self) -> None:
        """With more than one worker and training, every planned training at once (their
        data first, simulated with all workers where missing)."""
        spec, jobs = self.spec, self.jobs
        if spec.workers < 2 or len(jobs) < 2:
            return
        for job in jobs:
            if job.dataset is not None:
                ensure_dataset(replace(spec, dataset=job.dataset))
        self.on_stage(f"training {len(jobs)} models, {min(spec.workers, len(jobs))} at a time")
        self.ahead = self.timer.measure(
            "trained_ahead_wall_s", train_ahead, spec, jobs, self.trained
        )

    def train_own(self, sets: Sets) -> TrainedModel:
        """The run's own model, on its split's `sets`."""
        self.announce(self.jobs[0])
        model, _, _, _ = self.timer.measure(
            "training_s", fit, self.spec, self.dataset, self.jobs[0], sets
        )
        self.model = model
        return model

    def retrain(self, split: str, variant: str) -> TrainedOnSplit:
        """The same architecture trained on another split or variant of the run's dataset."""
        return self.retrain_on(None, split, variant)

    def retrain_on(self, did: str | None, split: str, variant: str) -> TrainedOnSplit:
        """Train on dataset `did` (a noisy variant: made when missing; None: the run's own),
        same split, seed and configuration, leaving out this run's test trajectories."""
        # the data and the training, both inside the evaluation's time like any retraining
        job = TrainingJob(did, split, variant)
        self.announce(job)
        other, _, sets, data = self.timer.measure(RETRAINING_KEY, fit, self.spec, self.dataset, job)
        made = provenance(other, data, job, self.spec.seed)
        return TrainedOnSplit(split, variant, other.predict, sets[2], made)

    def settle_timings(self) -> None:
        """Each second counted once: evaluators retrain inside their own time, and a
        training made ahead counts its own time, wherever it ran (the parallel stage's wall
        time is trained_ahead_wall_s)."""
        timings = self.timer.timings
        timings["evaluation_s"] -= timings.get(RETRAINING_KEY, 0.0)
        for job, seconds in self.ahead.items():
            self.timer.add("training_s" if job == self.jobs[0] else RETRAINING_KEY, seconds)

"""One benchmark run as a pipeline: resolve, data, training, evaluation, record; and the
record body built from the run's pieces.

Every model of a comparison goes through this same path, so they see the same samples, the
same protocol and the same evaluators; the record says exactly what was done. A record
already at the run's path of another configuration is never replaced unless the run says so
(`overwrite`, `identity`).
"""

from __future__ import annotations

from collections.abc import Callable
from datetime import UTC, datetime
from typing import Any

from symbench.core.common.errors import SymbenchError
from symbench.core.common.paths import writable_folder
from symbench.core.config.protocols import Paper
from symbench.core.config.provenance import (
    build_hyperparameters,
    checkpoint_file_hashes,
    git_commit,
    hardware,
    library_versions,
    plugin_info,
)
from symbench.core.data.dataset import Dataset
from symbench.core.plugin import registry
from symbench.core.robot.specs import split_variant
from symbench.core.runs.evaluation import run_evaluators
from symbench.core.runs.identity import check_replaceable
from symbench.core.runs.planning import evaluation_context, planned_trainings
from symbench.core.runs.results import (
    DatasetInfo,
    ModelInfo,
    RecordBody,
    ResultRecord,
    RobotPlugin,
    SampleCounts,
    TrainingInfo,
    write_record,
)
from symbench.core.runs.run_config import check_names, recorded_config, train_config
from symbench.core.runs.spec import RunSpec, checkpoint_root, ensure_dataset, model_entry
from symbench.core.runs.timing import CPU_KEY, Timer, cpu_seconds
from symbench.core.runs.trainings import RunTrainings, Sets
from symbench.core.training.kernels import training_kernels
from symbench.core.training.loop import batches_per_epoch
from symbench.core.training.resume import BEST_DIR
from symbench.core.training.trained_model import TrainedModel

__all__ = ["RunSpec", "record_body", "run"]


def _quiet(stage: str) -> None:
    """The default `on_stage`: says nothing."""


def run(spec: RunSpec, on_stage: Callable[[str], None] = _quiet) -> ResultRecord:
    """Train and evaluate one model; writes and returns the validated record. With more than
    one worker, the trainings the evaluators declare run beside the run's own, in parallel."""
    check_names(spec)
    writable_folder(spec.output, "output folder")
    check_replaceable(spec)  # before any minute is spent
    entry = model_entry(spec)
    timer, cpu_at_start = Timer(), cpu_seconds()
    on_stage("dataset")
    dataset = timer.measure("dataset_s", ensure_dataset, spec)
    check_replaceable(spec, dataset.content_hash)
    sets = dataset.split_views(entry.view, entry.variant, spec.split, spec.seed)
    trainings = RunTrainings(spec, dataset, timer, on_stage)
    context = evaluation_context(
        spec, dataset, sets[2], trainings.predict, trainings.retrain, trainings.retrain_on
    )
    trainings.jobs = planned_trainings(context, spec.evaluators)
    trainings.train_ahead()
    model = trainings.train_own(sets)
    metrics = timer.measure(
        "evaluation_s",
        run_evaluators,
        list(spec.evaluators),
        context,
        timer,
        lambda name: on_stage(f"evaluating {name}"),
    )
    trainings.settle_timings()
    timer.add(CPU_KEY, cpu_seconds() - cpu_at_start)
    record = record_body(spec, dataset, sets, model, metrics, timer.timings)
    if record.key() != spec.key():
        raise SymbenchError(f"internal: record key {record.key()} != run key {spec.key()}")
    return write_record(record, spec.record_path)


def robot_plugin(robot: str) -> RobotPlugin:
    """The plugin that registered `robot` (a variant's: its robot's), as a record names it."""
    info = registry.provider("robots", split_variant(robot)[0])
    return RobotPlugin(plugin=info.name, distribution=info.distribution, version=info.version)


def record_body(
    spec: RunSpec,
    dataset: Dataset,
    sets: Sets,
    model: TrainedModel,
    metrics: dict[str, dict[str, Any]],
    timings: dict[str, float],
) -> RecordBody:
    """The record of a finished run: its model, data, split sizes, training and metrics,
    with the hardware, library versions and commit it ran on."""
    entry = model_entry(spec)
    config = train_config(spec)
    parts = dataset.split_indices(spec.split, spec.seed)
    train_set, val_set, test_set = sets
    if isinstance(config.schedule, Paper):
        epochs = len(model.history["train_loss"])
    else:  # full passes over the training data
        epochs = model.steps // batches_per_epoch(len(train_set), config.batch_size)
    checkpoints = checkpoint_root(spec.output, spec.key(), dataset.content_hash)
    best = checkpoints / f"{spec.split}__{entry.variant}" / BEST_DIR
    return RecordBody(
        created=datetime.now(UTC).isoformat(timespec="seconds"),
        model=ModelInfo.model_validate(
            {
                "name": entry.name,
                "backend": entry.backend,
                "view": entry.view,
                "variant": entry.variant,
                "equivariant": entry.equivariant,
                "hyperparameters": build_hyperparameters(entry, config.hyper),
                "learning_rate": config.rate_for(entry),
                "parameters": model.n_params,
                "plugin": plugin_info(entry),
                "version": entry.version,
                "matched_parameters": spec.parameters,
                "sizes": dict(spec.sizes) or None,
            }
        ),
        robot=spec.robot,
        robot_plugin=robot_plugin(spec.robot),
        dataset=DatasetInfo.model_validate(
            {
                "id": dataset.id,
                "content_hash": dataset.content_hash,
                "robot_spec_hash": dataset.metadata["robot_spec_hash"],
                "preset": spec.preset,
            }
        ),
        split=spec.split,
        seed=spec.seed,
        samples=SampleCounts.model_validate(
            {
                "train": len(train_set),
                "val": len(val_set),
                "test": len(test_set),
                "train_trajectories": len(parts.train),
                "val_trajectories": len(parts.val),
                "test_trajectories": len(parts.test),
            }
        ),
        training=TrainingInfo.model_validate(
            {
                "epochs": epochs,
                "best_epoch": model.best_epoch,
                "stopped_early": model.stopped_by in ("patience", "overfitting-rule"),
                "stopped_by": model.stopped_by,
                "stop_reason": model.stopped,
                "steps": model.steps,
                "best_step": model.best_step,
                "best_val_loss": float(min(model.history["val_loss"])),
                "batch_size": config.batch_size,
                "config": recorded_config(config, entry),
                "checkpoint_sha256": checkpoint_file_hashes(best),
            }
        ),
        metrics=metrics,
        timings_s=timings,
        hardware={**hardware(), "training_kernels": training_kernels(entry.backend)},
        versions=library_versions(),
        git_commit=git_commit(),
    )

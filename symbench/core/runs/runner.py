"""One benchmark run: dataset -> split -> training -> evaluators -> validated result record.

Every model of a comparison goes through this same path, so they see the same samples, the
same protocol and the same evaluators; the record says exactly what was done.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from dataclasses import dataclass, field, replace
from datetime import UTC, datetime
from pathlib import Path
from typing import TYPE_CHECKING, Any

from symbench.core.common.errors import SymbenchError, UnknownNameError
from symbench.core.common.paths import writable_folder
from symbench.core.data.presets import preset
from symbench.core.data.provenance import (
    build_hyperparameters,
    checkpoint_file_hashes,
    git_commit,
    hardware,
    library_versions,
    plugin_info,
)
from symbench.core.data.schema import VARIANTS
from symbench.core.plugin import registry
from symbench.core.plugin.entries import ModelEntry
from symbench.core.runs.evaluation import EvaluationContext, TrainedOnSplit, run_evaluators
from symbench.core.runs.results import (
    DatasetInfo,
    ModelInfo,
    RecordBody,
    ResultRecord,
    SampleCounts,
    TrainingInfo,
    write_record,
)

if TYPE_CHECKING:
    from symbench.core.training.loop import TrainConfig

# The full evaluation (sweeps, boards); `symbench run` starts with the first-result set, which
# needs one training only: generalization trains twice more and closed-loop once more.
DEFAULT_EVALUATORS = ("torque-error", "equivariance", "invariance", "generalization", "closed-loop")
FIRST_RESULT_EVALUATORS = ("torque-error", "equivariance", "invariance")


@dataclass(frozen=True)
class RunSpec:
    model: str
    robot: str
    backend: str = "torch"
    split: str = "iid"
    seed: int = 0
    preset: str = "small"
    variant: str | None = None  # None: the model's registered input variant
    evaluators: tuple[str, ...] = DEFAULT_EVALUATORS
    output: Path = Path("results")
    workers: int = 2
    progress: bool = True
    max_epochs: int | None = None  # None: the preset's cap
    # TrainConfig fields replacing the protocol's defaults (`symbench verify` replays a
    # record's); seed, max_epochs and progress always come from the fields above
    train_config: dict[str, Any] = field(default_factory=dict)

    def key(self) -> str:
        """Matches `ResultRecord.key()`: the variant is resolved from the registry."""
        variant = model_entry(self).variant
        return (
            f"{self.robot}__{self.split}__{self.model}__{variant}__{self.backend}__seed{self.seed}"
        )

    @property
    def record_path(self) -> Path:
        return self.output / f"{self.key()}.json"


@dataclass
class Timer:
    timings: dict[str, float] = field(default_factory=dict)

    def measure(self, name: str, fn: Callable, *args, **kwargs):
        start = time.perf_counter()
        try:
            return fn(*args, **kwargs)
        finally:
            self.timings[name] = self.timings.get(name, 0.0) + time.perf_counter() - start


def model_entry(spec: RunSpec):
    """The registered model, with the run's input variant when it names one."""
    entry = registry.model(spec.model, spec.backend)
    if spec.variant is None:
        return entry
    if spec.variant not in VARIANTS:
        raise UnknownNameError("input variant", spec.variant, VARIANTS)
    return replace(entry, variant=spec.variant)


def check_names(spec: RunSpec) -> None:
    """Every name resolves and every number is valid before any minute is spent (closest
    names otherwise)."""
    model_entry(spec)
    registry.robot(spec.robot)
    registry.split(spec.split)
    for name in spec.evaluators:
        registry.evaluator(name)
    preset(spec.preset)
    if spec.workers < 1:
        raise SymbenchError(f"workers must be at least 1, got {spec.workers}")
    train_config(spec)


def train_config(spec: RunSpec) -> TrainConfig:
    """The run's training configuration (checked: seed, epoch cap, ...)."""
    from symbench.core.training.loop import TrainConfig

    cap = preset(spec.preset).training.max_epochs
    max_epochs = cap if spec.max_epochs is None else spec.max_epochs
    return TrainConfig(
        **{
            **spec.train_config,
            "seed": spec.seed,
            "progress": spec.progress,
            "max_epochs": max_epochs,
        }
    )


def ensure_dataset(spec: RunSpec):
    """The preset's dataset for the robot, generated first when it is not in the cache."""
    from symbench.core.data.generation import ensure_dataset as ensure

    return ensure(spec.robot, spec.preset, spec.workers, show_progress=spec.progress)


def recorded_config(config: TrainConfig, entry: ModelEntry) -> dict[str, Any]:
    """The TrainConfig as the record keeps it: defaults resolved, the progress bar left out."""
    from symbench.core.training.backends import get_backend

    out = {k: v for k, v in config.to_dict().items() if k != "progress"}
    out["learning_rate"] = config.rate_for(entry)
    out["compile"] = (
        get_backend(entry.backend).default_compiled if config.compile is None else config.compile
    )
    return out


def run(spec: RunSpec, on_stage: Callable[[str], None] = lambda stage: None) -> ResultRecord:
    """Train and evaluate one model; writes and returns the validated record."""
    from symbench.core.training.loop import train
    from symbench.core.training.resume import BEST_DIR

    check_names(spec)
    writable_folder(spec.output, "output folder")
    entry = model_entry(spec)
    config = train_config(spec)
    timer = Timer()
    on_stage("dataset")
    dataset = timer.measure("dataset_s", ensure_dataset, spec)
    # per dataset version, so a regenerated dataset trains afresh instead of resuming
    checkpoints = spec.output / "checkpoints" / spec.key() / dataset.content_hash[:12]

    def train_on(split: str, variant: str):
        model_of = replace(entry, variant=variant)
        parts = dataset.split_indices(split, spec.seed)
        train_set, val_set, test_set = dataset.split_views(entry.view, variant, split, spec.seed)
        model = train(
            model_of, train_set, val_set, config, checkpoint_dir=checkpoints / f"{split}__{variant}"
        )
        return model, parts, (train_set, val_set, test_set)

    on_stage("training")
    model, parts, (train_set, val_set, test_set) = timer.measure(
        "training_s", train_on, spec.split, entry.variant
    )
    best_checkpoint = checkpoint_file_hashes(
        checkpoints / f"{spec.split}__{entry.variant}" / BEST_DIR
    )

    def retrain(split: str, variant: str) -> TrainedOnSplit:
        on_stage(f"training on {split} ({variant} variant)")
        other, _, (_, _, other_test) = timer.measure("retraining_s", train_on, split, variant)
        return TrainedOnSplit(split, variant, other.predict, other_test)

    context = EvaluationContext(
        entry=entry,
        dataset=dataset,
        preset=preset(spec.preset),
        split=spec.split,
        seed=spec.seed,
        predict=model.predict,
        test=test_set,
        test_trajectories=parts.test,
        output_dir=spec.output,
        retrain=retrain,
    )
    metrics = timer.measure(
        "evaluation_s",
        run_evaluators,
        list(spec.evaluators),
        context,
        lambda name: on_stage(f"evaluating {name}"),
    )
    # evaluators retrain inside their own time: report each second once
    timer.timings["evaluation_s"] -= timer.timings.get("retraining_s", 0.0)
    epochs = len(model.history["train_loss"])
    record = RecordBody(
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
            }
        ),
        robot=spec.robot,
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
                "stopped_early": epochs < config.max_epochs,
                "best_val_loss": float(min(model.history["val_loss"])),
                "batch_size": config.batch_size,
                "config": recorded_config(config, entry),
                "checkpoint_sha256": best_checkpoint,
            }
        ),
        metrics=metrics,
        timings_s=timer.timings,
        hardware=hardware(),
        versions=library_versions(),
        git_commit=git_commit(),
    )
    if record.key() != spec.key():
        raise SymbenchError(f"internal: record key {record.key()} != run key {spec.key()}")
    return write_record(record, spec.record_path)

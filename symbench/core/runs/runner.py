"""One benchmark run: dataset -> split -> training -> evaluators -> validated result record.

Every model of a comparison goes through this same path, so they see the same samples, the
same protocol and the same evaluators; the record says exactly what was done.

The data and the budgets are chosen apart: the dataset (`RunSpec.dataset`, any cached id,
generated or imported; by default the standard dataset of the robot and preset) names the
trajectories, the preset the epoch cap and the evaluators' budgets. The record's file name is
the run's key (`results.run_key`), which holds both, and a record already there of another
configuration is never replaced unless the run says so (`overwrite`).
"""

from __future__ import annotations

import functools
import json
import re
import time
from collections.abc import Callable
from dataclasses import dataclass, field, replace
from datetime import UTC, datetime
from pathlib import Path
from typing import TYPE_CHECKING, Any, Literal

from symbench.core.common.errors import SymbenchError, UnknownNameError
from symbench.core.common.paths import writable_folder
from symbench.core.config.presets import dataset_id, parse_dataset_id, preset
from symbench.core.config.protocols import PROTOCOLS, STEP_BUDGET
from symbench.core.config.provenance import (
    build_hyperparameters,
    checkpoint_file_hashes,
    git_commit,
    hardware,
    library_versions,
    plugin_info,
)
from symbench.core.data.splits import check_split
from symbench.core.data.views.schema import VARIANTS
from symbench.core.plugin import registry
from symbench.core.plugin.entries import ModelEntry
from symbench.core.robot.specs import registered_robot
from symbench.core.runs.evaluation import EvaluationContext, TrainedOnSplit, run_evaluators
from symbench.core.runs.results import (
    IDENTIFIER,
    DatasetInfo,
    ModelInfo,
    RecordBody,
    ResultRecord,
    SampleCounts,
    TrainingInfo,
    read_record,
    run_key,
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
    robot: str  # must be the dataset's robot
    backend: str = "torch"
    split: str = "iid"  # a registered split, or a column split (`splits.column_split`) name
    seed: int = 0
    preset: str = "small"
    variant: str | None = None  # None: the model's registered input variant
    evaluators: tuple[str, ...] = DEFAULT_EVALUATORS
    output: Path = Path("results")
    workers: int = 2
    progress: bool = True
    protocol: str = "converge"  # the training protocol (symbench.core.training.loop)
    max_steps: int | None = None  # None: the preset's budget (converge, cosine)
    max_epochs: int | None = None  # None: the preset's cap (paper)
    parameters: int | None = None  # the model's widths scaled to this parameter count
    sizes: tuple[tuple[str, int], ...] = ()  # build keywords set by name (`--size`), last
    # TrainConfig fields replacing the protocol's defaults (`symbench verify` replays a
    # record's); seed, protocol, budgets and progress always come from the fields above
    train_config: dict[str, Any] = field(default_factory=dict)
    dataset: str | None = None  # a cached dataset id; None: the robot's standard one (preset's)
    overwrite: bool = False  # replace a record of another configuration at `record_path`

    @property
    def dataset_id(self) -> str:
        """The data the run trains on: `dataset`, else the standard dataset of the preset."""
        return self.dataset if self.dataset is not None else dataset_id(self.robot, self.preset)

    def key(self) -> str:
        """Matches `ResultRecord.key()`: the variant is resolved from the registry."""
        variant = model_entry(self).variant
        return run_key(
            self.dataset_id,
            self.preset,
            self.split,
            self.model,
            variant,
            self.backend,
            self.protocol,
            self.seed,
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


def checkpoint_root(output: Path, key: str, content_hash: str) -> Path:
    """Where a run keeps its checkpoints: per run key and dataset version (its content hash),
    so a regenerated dataset trains afresh instead of resuming; a retraining on another
    dataset lies under `<dataset id>-<hash>/`, each training in `<split>__<variant>/`."""
    return Path(output) / "checkpoints" / key / content_hash[:12]


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
    names otherwise); the dataset exists (or is a standard one, made when missing) and holds
    the run's robot."""
    entry = model_entry(spec)
    unknown = sorted(set(dict(spec.sizes)) - set(build_hyperparameters(entry, {})))
    if unknown:
        raise SymbenchError(
            f"model {entry.name} has no build keyword {', '.join(unknown)} (it has: "
            f"{', '.join(build_hyperparameters(entry, {})) or 'none'})"
        )
    registered_robot(spec.robot)
    check_split(spec.split)  # a registered split, or a column split's name
    for name in spec.evaluators:
        registry.evaluator(name)
    preset(spec.preset)
    if spec.workers < 1:
        raise SymbenchError(f"workers must be at least 1, got {spec.workers}")
    train_config(spec)
    resolve_robot(spec.robot, spec.dataset_id)


def is_standard(did: str) -> bool:
    """Whether `did` is the id this code generates for a robot and preset (made when missing)."""
    parsed = parse_dataset_id(did)
    return parsed is not None and dataset_id(*parsed) == did


def default_preset(did: str | None) -> str:
    """The preset of a run that names none: a standard dataset's own, else `small`."""
    parsed = parse_dataset_id(did) if did is not None else None
    return parsed[1] if parsed is not None else "small"


def dataset_robot(did: str) -> str:
    """The robot whose trajectories dataset `did` holds: its metadata's when it is cached, a
    standard id's robot otherwise; an error for any other id missing from the cache."""
    from symbench.core.data.dataset import missing_hint
    from symbench.core.data.storage.metadata import METADATA, dataset_dir, read_metadata

    if not re.match(IDENTIFIER, did) or len(did) > 100:
        raise SymbenchError(
            f"dataset id '{did}' cannot name a result record (at most 100 letters, digits, "
            "'.', '_' and '-', not starting with '.')"
        )
    if (dataset_dir(did) / METADATA).is_file():
        return str(read_metadata(did, missing_hint(did))[1]["robot"])
    if is_standard(did):
        return str(parse_dataset_id(did)[0])  # type: ignore[index]  # standard: parsed
    raise SymbenchError(f"dataset '{did}' is not in the cache; {missing_hint(did)}")


def resolve_robot(robot: str | None, did: str) -> str:
    """The robot of a run on dataset `did`: the dataset's; `robot`, when given, must be it."""
    holds = dataset_robot(did)
    if robot is not None and robot != holds:
        raise SymbenchError(
            f"dataset '{did}' holds trajectories of {holds}, not {robot}; "
            "leave --robot out or give the dataset's robot"
        )
    return holds


def train_config(spec: RunSpec) -> TrainConfig:
    """The run's training configuration: the protocol with the preset's budgets (checked:
    seed, budgets, ...). A budget of another protocol is refused, not ignored."""
    from symbench.core.training.loop import TrainConfig

    budget = preset(spec.preset).training
    steps = spec.protocol in STEP_BUDGET
    field, option = ("max_epochs", "--max-epochs") if steps else ("max_steps", "--max-steps")
    if spec.protocol in PROTOCOLS and getattr(spec, field) is not None:
        raise SymbenchError(
            f"{option} is a budget of another protocol, not of "
            f"'{spec.protocol}' (converge, cosine: --max-steps; paper: --max-epochs)"
        )
    hyper = {**(matched_size(spec) if spec.parameters is not None else {}), **dict(spec.sizes)}
    return TrainConfig(
        **{
            "eval_every": budget.eval_every,
            "patience": budget.patience,
            "val_stride": budget.val_stride,
            **({"hyper": hyper} if hyper else {}),
            **spec.train_config,
            "seed": spec.seed,
            "progress": spec.progress,
            "protocol": spec.protocol,
            "max_steps": budget.max_steps if spec.max_steps is None else spec.max_steps,
            "max_epochs": budget.max_epochs if spec.max_epochs is None else spec.max_epochs,
        }
    )


def matched_size(spec: RunSpec) -> dict[str, int]:
    """The width keywords that give the run's model `spec.parameters` parameters on the
    robot's data (its view's shapes follow from the leg count)."""
    from symbench.core.robot.specs import load_robot

    assert spec.parameters is not None
    entry = model_entry(spec)
    n_legs = load_robot(spec.robot).n_legs
    return dict(_matched(entry.name, entry.backend, entry.variant, n_legs, spec.parameters))


@functools.lru_cache(maxsize=64)
def _matched(
    model: str, backend: str, variant: str, n_legs: int, parameters: int
) -> tuple[tuple[str, int], ...]:
    """Found once per process: a run asks for its configuration several times (plan,
    record check, training), and each search builds about a dozen networks."""
    from symbench.core.data.views.model_dims import dims_for
    from symbench.core.training.sizes import matched_widths

    entry = replace(registry.model(model, backend), variant=variant)
    dims = dims_for(entry.view, entry.variant, n_legs)
    return tuple(matched_widths(entry, dims, parameters).items())


def budget_text(config: TrainConfig) -> str:
    """The training's budget in words, for plans and tables."""
    if config.protocol == "paper":
        return f"paper protocol, at most {config.max_epochs} epochs"
    return (
        f"{config.protocol} protocol, at most {config.max_steps} steps, patience "
        f"{config.patience} x {config.eval_every} steps"
    )


def ensure_dataset(spec: RunSpec):
    """The run's dataset: a standard one is generated first when it is not in the cache (or
    its robot spec changed); any other (imported) must be in the cache."""
    from symbench.core.data.dataset import load_dataset
    from symbench.core.data.generation.generate import ensure_dataset as ensure

    did = spec.dataset_id
    if is_standard(did):
        robot, grid = parse_dataset_id(did)  # type: ignore[misc]  # standard: parsed
        dataset = ensure(robot, grid, spec.workers, show_progress=spec.progress)
    else:
        dataset = load_dataset(did)
    if dataset.robot != spec.robot:
        raise SymbenchError(
            f"dataset '{did}' holds trajectories of {dataset.robot}, not {spec.robot}"
        )
    return dataset


def recorded_config(config: TrainConfig, entry: ModelEntry) -> dict[str, Any]:
    """The TrainConfig as the record keeps it: defaults resolved, the progress bar left out."""
    from symbench.core.training.backends import get_backend

    out = {k: v for k, v in config.to_dict().items() if k != "progress"}
    out["val_stride"] = config.val_stride  # to_dict leaves it out at 1; records always say
    out["learning_rate"] = config.rate_for(entry)
    out["compile"] = (
        get_backend(entry.backend).default_compiled if config.compile is None else config.compile
    )
    return out


def configuration(spec: RunSpec, content_hash: str | None = None) -> dict[str, Any]:
    """What the run would record as its configuration (`RecordBody.configuration`); the
    dataset content hash only when given (it is known once the dataset is made)."""
    entry = model_entry(spec)
    config = train_config(spec)
    wanted = {
        "dataset": spec.dataset_id,
        "dataset content hash": content_hash,
        "preset": spec.preset,
        "robot": spec.robot,
        "split": spec.split,
        "seed": spec.seed,
        "model": entry.name,
        "backend": entry.backend,
        "input variant": entry.variant,
        "evaluators": sorted(spec.evaluators),
        "hyper-parameters": build_hyperparameters(entry, config.hyper),
        **{f"training {k}": v for k, v in recorded_config(config, entry).items()},
    }
    if content_hash is None:
        del wanted["dataset content hash"]
    return json.loads(json.dumps(wanted))  # as a record holds them: tuples become lists


def _shown(name: str, value: Any) -> str:
    if name == "dataset content hash" and isinstance(value, str):
        return f"{value[:12]}..."
    if name == "evaluators" and isinstance(value, list):
        return ",".join(map(str, value)) or "none"
    return json.dumps(value) if not isinstance(value, str) else value


def difference(found: dict[str, Any], wanted: dict[str, Any]) -> str | None:
    """The first configuration entry in which a found record differs from a wanted run, as
    "preset smoke in the record, small in this run"; None when they agree on every wanted
    entry."""
    for name, value in wanted.items():
        if found.get(name) != value:
            was = _shown(name, found.get(name))
            return f"{name} {was} in the record, {_shown(name, value)} in this run"
    return None


RecordState = Literal["missing", "unreadable", "same", "different"]


def record_state(spec: RunSpec, content_hash: str | None = None) -> tuple[RecordState, str]:
    """What is at the run's record path: nothing, a record that cannot be trusted (corrupt,
    edited, schema 1: rewritten), a record of this very configuration, or one of another
    configuration; with the reason when untrusted or of another configuration."""
    path = spec.record_path
    if not path.is_file():
        return "missing", ""
    try:
        record = read_record(path)
    except SymbenchError as exc:
        return "unreadable", str(exc)
    why = difference(record.configuration(), configuration(spec, content_hash))
    return ("same", "") if why is None else ("different", why)


def refusal(spec: RunSpec, why: str, more: int = 0) -> SymbenchError:
    """The error for a record of another configuration at the run's path (`more`: how many
    other records of the command differ too)."""
    others = f" (and {more} more record{'s' if more > 1 else ''})" if more else ""
    it = "them" if more else "it"
    return SymbenchError(
        f"{spec.record_path} is a record of another configuration ({why}){others}; pass "
        f"--overwrite to run {it} again and replace {it}, or choose another --output"
    )


def _check_replaceable(spec: RunSpec, content_hash: str | None = None) -> None:
    state, why = record_state(spec, content_hash)
    if state == "different" and not spec.overwrite:
        raise refusal(spec, why)


@dataclass(frozen=True)
class TrainingJob:
    """One training a run needs: on dataset `dataset` (None: the run's own), its `split` and
    input `variant`, with the run's seed and configuration."""

    dataset: str | None
    split: str
    variant: str


def fit(spec: RunSpec, dataset, job: TrainingJob, sets: tuple | None = None):
    """Trains `job` into the run's checkpoint folder, or loads it when a finished training is
    there (`train_ahead` made it, or an earlier, interrupted run): (model, the split's
    trajectory ids, its (train, val, test) views). On another dataset (a noisy variant for
    control) the run's test trajectories are left out of training and validation (same grid:
    same ids). `sets`: the views of a split of the run's own dataset, when already made."""
    import numpy as np

    from symbench.core.training.loop import train

    entry = replace(model_entry(spec), variant=job.variant)
    root = checkpoint_root(spec.output, spec.key(), dataset.content_hash)
    if job.dataset is None or job.dataset == dataset.id:
        parts = dataset.split_indices(job.split, spec.seed)
        if sets is None:
            sets = dataset.split_views(entry.view, job.variant, job.split, spec.seed)
        folder = root / f"{job.split}__{job.variant}"
    else:
        other = ensure_dataset(replace(spec, dataset=job.dataset))
        held_out = dataset.split_indices(spec.split, spec.seed).test
        parts = other.split_indices(job.split, spec.seed)
        ids = (np.setdiff1d(parts.train, held_out), np.setdiff1d(parts.val, held_out), parts.test)
        arrays = other.view(entry.view, job.variant)
        sets = tuple(arrays.take(np.isin(arrays.trajectory, i)) for i in ids)
        folder = root / f"{other.id}-{other.content_hash[:12]}" / f"{job.split}__{job.variant}"
    model = train(entry, sets[0], sets[1], train_config(spec), checkpoint_dir=folder)
    return model, parts, sets


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
    from symbench.core.common.processes import run_each

    seconds: dict[TrainingJob, float] = {}

    def done(result: tuple[TrainingJob, float]) -> None:
        seconds[result[0]] = result[1]
        on_done(result[0])

    quiet = replace(spec, progress=False, workers=1)
    run_each(_fit_in_worker, [(quiet, job) for job in jobs], spec.workers, done)
    return seconds


def planned_trainings(context: EvaluationContext, names: tuple[str, ...]) -> list[TrainingJob]:
    """The trainings the run's evaluators say they will ask for (`EvaluatorEntry.trainings`),
    without repeats; the run's own training first."""
    from symbench.core.runs.evaluation import skip_reason

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


def _not_while_planning(*_: object) -> Any:
    raise SymbenchError("trainings() may declare trainings, not run them")


def evaluation_context(
    spec: RunSpec,
    dataset: Any,
    test: Any,
    predict: Callable[[Any], Any],
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


class _TestSamplesWhilePlanning:
    """The context's `test` while a sweep plans: its samples are not made yet (building a
    view of a `paper` dataset costs tens of seconds, once per run, not per planned run)."""

    def __getattr__(self, name: str) -> Any:
        raise SymbenchError(
            "trainings() runs while a sweep plans, before the test samples are made: "
            "declare trainings from the context's split, preset and dataset"
        )


def declared_datasets(spec: RunSpec, dataset) -> list[str]:
    """The other datasets the run's evaluators declare trainings on (the closed loop's noisy
    variant), so that a sweep makes each once before runs that need it start side by side."""
    planning = _not_while_planning
    test = _TestSamplesWhilePlanning()
    context = evaluation_context(spec, dataset, test, planning, planning, planning)
    jobs = planned_trainings(context, spec.evaluators)
    return [job.dataset for job in jobs if job.dataset is not None]


def run(spec: RunSpec, on_stage: Callable[[str], None] = lambda stage: None) -> ResultRecord:
    """Train and evaluate one model; writes and returns the validated record. With more than
    one worker, the trainings the evaluators declare run beside the run's own, in parallel."""
    from symbench.core.training.loop import batches_per_epoch
    from symbench.core.training.resume import BEST_DIR

    check_names(spec)
    writable_folder(spec.output, "output folder")
    _check_replaceable(spec)  # before any minute is spent
    entry = model_entry(spec)
    config = train_config(spec)
    timer = Timer()
    on_stage("dataset")
    dataset = timer.measure("dataset_s", ensure_dataset, spec)
    _check_replaceable(spec, dataset.content_hash)
    checkpoints = checkpoint_root(spec.output, spec.key(), dataset.content_hash)
    parts = dataset.split_indices(spec.split, spec.seed)
    train_set, val_set, test_set = dataset.split_views(
        entry.view, entry.variant, spec.split, spec.seed
    )
    trained: list = []  # the run's own model, once trained

    def announce(job: TrainingJob) -> None:
        """Says whether the stage trains, or loads what `train_ahead` trained."""
        verb = "loading the model trained ahead" if job in ahead else "training"
        target = f"{job.dataset} {job.split}" if job.dataset else job.split
        on_stage(verb if job == jobs[0] else f"{verb} on {target} ({job.variant} variant)")

    def retrain(split: str, variant: str) -> TrainedOnSplit:
        job = TrainingJob(None, split, variant)
        announce(job)
        other, _, (_, _, other_test) = timer.measure("retraining_s", fit, spec, dataset, job)
        return TrainedOnSplit(split, variant, other.predict, other_test)

    def retrain_on(did: str, split: str, variant: str) -> TrainedOnSplit:
        """Train on dataset `did` (a noisy variant: made when missing), same split, seed and
        configuration, leaving out this run's test trajectories."""
        # the data and the training, both inside the evaluation's time like any retraining
        job = TrainingJob(did, split, variant)
        announce(job)
        other, _, sets = timer.measure("retraining_s", fit, spec, dataset, job)
        return TrainedOnSplit(split, variant, other.predict, sets[2])

    context = evaluation_context(
        spec, dataset, test_set, lambda inputs: trained[0].predict(inputs), retrain, retrain_on
    )
    jobs = planned_trainings(context, spec.evaluators)
    ahead: dict[TrainingJob, float] = {}

    def trained_one(job: TrainingJob) -> None:
        on_stage(f"trained on {job.dataset or dataset.id} {job.split} ({job.variant} variant)")

    if spec.workers > 1 and len(jobs) > 1:
        for job in jobs:  # the data first, simulated with all workers where missing
            if job.dataset is not None:
                ensure_dataset(replace(spec, dataset=job.dataset))
        on_stage(f"training {len(jobs)} models, {min(spec.workers, len(jobs))} at a time")
        ahead = timer.measure(
            "trained_ahead_wall_s",
            train_ahead,
            spec,
            jobs,
            trained_one,
        )
    announce(jobs[0])
    model, _, _ = timer.measure(
        "training_s", fit, spec, dataset, jobs[0], (train_set, val_set, test_set)
    )
    trained.append(model)
    best_checkpoint = checkpoint_file_hashes(
        checkpoints / f"{spec.split}__{entry.variant}" / BEST_DIR
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
    # a training made ahead counts its own time, wherever it ran (the parallel stage's wall
    # time is trained_ahead_wall_s)
    for job, seconds in ahead.items():
        name = "training_s" if job == jobs[0] else "retraining_s"
        timer.timings[name] = timer.timings.get(name, 0.0) + seconds
    if config.protocol == "paper":
        epochs = len(model.history["train_loss"])
    else:  # full passes over the training data
        epochs = model.steps // batches_per_epoch(len(train_set), config.batch_size)
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
                "stopped_early": model.stopped_by in ("patience", "overfitting-rule"),
                "stopped_by": model.stopped_by,
                "stop_reason": model.stopped,
                "steps": model.steps,
                "best_step": model.best_step,
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

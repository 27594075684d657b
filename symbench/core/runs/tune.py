"""`symbench tune`: a small hyper-parameter search per model, on validation data only.

The grid is learning rate x width scale: the model's `widths` build keywords (its
`ModelEntry`) scaled together from their defaults. Every trial trains with the run's
protocol and budgets on the split's training trajectories and is scored by its best
validation loss (trajectories carved from the training side); the test trajectories are
never looked at. Trials live in an Optuna journal file, so a search started again skips
the trials it finished and a trial cut off by a crash is run again (a damaged journal is
refused, naming it: `tune_journal`). The summary (JSON,
rewritten atomically after every trial) names the best trial: a maintainer copies its
values into a built-in model's defaults (`symbench/plugins/architectures.py` and
`zoo.py`), a plugin author into their `ModelEntry`.
"""

from __future__ import annotations

import itertools
from collections.abc import Callable, Sequence
from dataclasses import asdict, dataclass, replace
from pathlib import Path
from typing import Any

from symbench.core.common.errors import SymbenchError
from symbench.core.config.protocols import Paper
from symbench.core.config.provenance import git_commit
from symbench.core.plugin.entries import ModelEntry
from symbench.core.runs.run_config import train_config
from symbench.core.runs.spec import RunSpec, ensure_dataset, model_entry
from symbench.core.runs.tune_journal import open_study
from symbench.core.training.checkpoints import write_json
from symbench.core.training.sizes import scaled_widths

DEFAULT_RATE_FACTORS = (1 / 3, 1.0, 3.0)  # around the model's own learning rate
DEFAULT_WIDTH_SCALES = (0.5, 1.0, 2.0)


@dataclass(frozen=True)
class Trial:
    """One point of the grid, trained and scored."""

    learning_rate: float
    width_scale: float
    hyper: dict[str, int]
    parameters: int
    best_val_loss: float
    steps: int
    stopped_by: str


def default_rates(entry: ModelEntry) -> tuple[float, ...]:
    return tuple(float(f"{entry.learning_rate * f:.3g}") for f in DEFAULT_RATE_FACTORS)


def summary_path(folder: Path, spec: RunSpec) -> Path:
    return Path(folder) / f"{spec.key()}.tune.json"


def journal_path(folder: Path, spec: RunSpec) -> Path:
    return Path(folder) / f"{spec.key()}.journal"


def tune(
    spec: RunSpec,
    learning_rates: Sequence[float],
    width_scales: Sequence[float],
    folder: Path,
    report: Callable[[str], None] = print,
) -> dict[str, Any]:
    """Train every (learning rate, width scale) of the grid not yet finished in `folder`'s
    journal; returns (and writes) the summary with every trial and the best one."""
    import optuna
    from optuna.distributions import BaseDistribution, FloatDistribution
    from optuna.trial import TrialState

    from symbench.core.training.loop import train

    entry = model_entry(spec)
    rates = tuple(float(r) for r in learning_rates)
    scales = tuple(float(s) for s in width_scales) if entry.widths else (1.0,)
    if not rates or any(not 0 < r < 1 for r in rates):
        raise SymbenchError(f"learning rates must be numbers in (0, 1), got {list(rates)}")
    if any(not 1e-3 <= s <= 1e3 for s in scales):
        raise SymbenchError(f"width scales must be in [0.001, 1000], got {list(scales)}")
    base = train_config(spec)
    dataset = ensure_dataset(spec)
    train_set, val_set, _ = dataset.split_views(entry.view, entry.variant, spec.split, spec.seed)
    Path(folder).mkdir(parents=True, exist_ok=True)
    optuna.logging.set_verbosity(optuna.logging.WARNING)
    study = open_study(journal_path(folder, spec), f"{spec.key()}__{dataset.content_hash[:12]}")
    for stale in study.get_trials(deepcopy=False, states=(TrialState.RUNNING,)):
        study.tell(stale.number, state=TrialState.FAIL)  # cut off by a crash: run again
    # fixed ranges, not the grid's values: a search started again with a larger grid (more
    # rates or widths) keeps the points it finished and runs only the new ones
    space: dict[str, BaseDistribution] = {
        "learning_rate": FloatDistribution(1e-9, 1.0, log=True),
        "width_scale": FloatDistribution(1e-3, 1e3, log=True),
    }
    grid = list(itertools.product(rates, scales))

    def finished() -> set[tuple[float, float]]:
        complete = study.get_trials(deepcopy=False, states=(TrialState.COMPLETE,))
        return {(t.params["learning_rate"], t.params["width_scale"]) for t in complete}

    while todo := [point for point in grid if point not in finished()]:
        if not study.get_trials(deepcopy=False, states=(TrialState.WAITING,)):
            study.enqueue_trial(dict(zip(space, todo[0], strict=True)))
        trial = study.ask(space)
        rate, scale = trial.params["learning_rate"], trial.params["width_scale"]
        hyper = scaled_widths(entry, scale) if entry.widths else {}
        report(f"trial {trial.number}: learning rate {rate:g}, width scale {scale:g} {hyper}")
        config = replace(base, learning_rate=rate, hyper=hyper, progress=False)
        model = train(entry, train_set, val_set, config)
        found = Trial(
            rate,
            scale,
            hyper,
            model.n_params,
            float(min(model.history["val_loss"])),
            model.steps,
            model.stopped_by,
        )
        for key, value in asdict(found).items():
            trial.set_user_attr(key, value)
        study.tell(trial, found.best_val_loss)
        write_json(summary_path(folder, spec), _summary(spec, dataset, base, study, grid))
    summary = _summary(spec, dataset, base, study, grid)
    write_json(summary_path(folder, spec), summary)
    return summary


def _summary(spec: RunSpec, dataset: Any, base: Any, study: Any, grid: list) -> dict[str, Any]:
    from optuna.trial import TrialState

    trials = [
        t.user_attrs
        for t in study.get_trials(deepcopy=False, states=(TrialState.COMPLETE,))
        if t.user_attrs
    ]
    trials.sort(key=lambda t: (t["learning_rate"], t["width_scale"]))
    best = min(trials, key=lambda t: t["best_val_loss"]) if trials else None
    return {
        "model": spec.model,
        "backend": spec.backend,
        "robot": spec.robot,
        "dataset": dataset.id,
        "dataset_content_hash": dataset.content_hash,
        "preset": spec.preset,
        "split": spec.split,
        "seed": spec.seed,
        "protocol": base.protocol,
        "budgets": {"max_epochs": base.schedule.max_epochs}
        if isinstance(base.schedule, Paper)
        else asdict(base.schedule),
        "scored_by": "best validation loss (normalized MSE, validation trajectories carved "
        "from the training side; test trajectories never used)",
        "grid": [{"learning_rate": r, "width_scale": s} for r, s in grid],
        "trials": trials,
        "complete": len(trials) == len(grid),
        "best": best,
        "git_commit": git_commit(),
    }

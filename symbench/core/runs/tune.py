"""`symbench tune`: a small hyper-parameter search per model, on validation data only.

The grid is learning rate x width scale: the model's `widths` build keywords (its
`ModelEntry`) scaled together from their defaults. Every trial trains with the run's
protocol and budgets on the split's training trajectories and is scored by its best
validation loss (trajectories carved from the training side); the test trajectories are
never looked at. Trials live in an Optuna journal file, so a search started again skips
the trials it finished and a trial cut off by a crash is run again (a damaged journal is
refused, naming it: `tune_journal`). When the best rate is the grid's smallest or
largest, the search goes on past that edge, one rate at a time at the best width, until the
best is interior (at most MAX_EXTENSIONS more rates): a best on the edge says only that the
grid was too narrow. The points it adds follow from the finished trials alone, so a search
started again finds the same ones. The summary (JSON, rewritten atomically after every
trial) names the best trial: `symbench tune summarize` turns summaries into the board's
table and the lines of a built-in model's `tuned_rates.toml` (its rate per robot); a plugin
author copies them into their `ModelEntry.learning_rates`.
"""

from __future__ import annotations

import itertools
from collections.abc import Callable, Sequence
from dataclasses import asdict, dataclass, field, replace
from pathlib import Path
from typing import Any

from symbench.core.common.errors import SymbenchError
from symbench.core.config.protocols import Paper
from symbench.core.config.provenance import git_commit
from symbench.core.data.views.model_dims import dims_for
from symbench.core.robot.specs import load_robot
from symbench.core.runs.run_config import train_config
from symbench.core.runs.spec import RunSpec, ensure_dataset, model_entry
from symbench.core.runs.tune_journal import open_study
from symbench.core.training.buildable import check_width_scales
from symbench.core.training.checkpoints import write_json
from symbench.core.training.sizes import scaled_widths

DEFAULT_RATE_FACTORS = (1 / 3, 1.0, 3.0)  # around the rate a run on the robot trains with
DEFAULT_WIDTH_SCALES = (0.5, 1.0, 2.0)
MAX_EXTENSIONS = 3  # rates an edge extension may add to a search
EDGE_RATIO = 3.0  # the step past an edge when the search has tried a single rate
RATE_RANGE = (1e-9, 1.0)  # the journal's learning rates: the lowest, and the bound above
# the journal's width scales: wider than a search may ask (MIN_SCALE to MAX_SCALE), as
# journals written before that bound say
SCALE_RANGE = (1e-3, 1e3)


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


def default_rates(spec: RunSpec) -> tuple[float, ...]:
    """The grid's rates around the one a run of `spec` trains with (the robot's tuned rate,
    else the model's)."""
    rate = train_config(spec).rate_for(model_entry(spec))
    return tuple(_rounded(rate * f) for f in DEFAULT_RATE_FACTORS)


def beyond_edge(rates: Sequence[float], best: float) -> float | None:
    """The next rate past the edge of `rates` that `best` sits on, one grid step (the ratio
    to its neighbour) further; None when `best` is interior or that rate would leave
    RATE_RANGE."""
    tried = sorted(set(rates))
    if best == tried[0]:
        rate = _rounded(best / (tried[1] / best if len(tried) > 1 else EDGE_RATIO))
    elif best == tried[-1]:
        rate = _rounded(best * best / tried[-2])
    else:
        return None
    return rate if RATE_RANGE[0] <= rate < RATE_RANGE[1] and rate not in tried else None


def on_edge(trials: Sequence[dict[str, Any]], best: dict[str, Any]) -> bool:
    """Whether the best trial's rate is the smallest or the largest of `trials`."""
    rates = [t["learning_rate"] for t in trials]
    return best["learning_rate"] in (min(rates), max(rates))


def _rounded(rate: float) -> float:
    return float(f"{rate:.3g}")


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
    extend_edges: bool = True,
) -> dict[str, Any]:
    """Train every (learning rate, width scale) of the grid not yet finished in `folder`'s
    journal, then (`extend_edges`) the rates past the edge the best sits on; returns (and
    writes) the summary with every trial and the best one."""
    import optuna
    from optuna.distributions import BaseDistribution, FloatDistribution
    from optuna.trial import TrialState

    from symbench.core.training.loop import train

    entry = model_entry(spec)
    rates = tuple(float(r) for r in learning_rates)
    scales = tuple(float(s) for s in width_scales) if entry.widths else (1.0,)
    if not rates or any(not 0 < r < 1 for r in rates):
        raise SymbenchError(f"learning rates must be numbers in (0, 1), got {list(rates)}")
    dims = dims_for(entry.view, entry.variant, load_robot(spec.robot).n_legs)
    check_width_scales(entry, dims, scales)  # before the dataset is made
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
        "learning_rate": FloatDistribution(RATE_RANGE[0], RATE_RANGE[1], log=True),
        "width_scale": FloatDistribution(*SCALE_RANGE, log=True),
    }
    search = Search(list(itertools.product(rates, scales)))

    def write() -> dict[str, Any]:
        summary = _summary(spec, dataset, base, study, search)
        write_json(summary_path(folder, spec), summary)
        return summary

    def finished() -> set[tuple[float, float]]:
        complete = study.get_trials(deepcopy=False, states=(TrialState.COMPLETE,))
        return {(t.params["learning_rate"], t.params["width_scale"]) for t in complete}

    def run_trial(point: tuple[float, float]) -> None:
        """Trains `point` (or the trial a crash left waiting) and records it in the journal."""
        if not study.get_trials(deepcopy=False, states=(TrialState.WAITING,)):
            study.enqueue_trial(dict(zip(space, point, strict=True)))
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
        write()

    while True:
        while todo := [point for point in search.points if point not in finished()]:
            run_trial(todo[0])
        if not (extend_edges and search.extend(_trials(study, search))):
            return write()
        report(f"the best rate is on the edge: next, {search.extension[-1][0]:g}")
        write()  # the rate added, not yet trained: the search is not complete


@dataclass
class Search:
    """The points a search trains: the grid, then one rate at a time past the edge the best
    trial sits on, at its width scale (`extension`)."""

    grid: list[tuple[float, float]]
    extension: list[tuple[float, float]] = field(default_factory=list)

    @property
    def points(self) -> list[tuple[float, float]]:
        return self.grid + self.extension

    def extend(self, trials: list[dict[str, Any]]) -> bool:
        """Adds the next rate past the best trial's edge; False when the best is interior,
        MAX_EXTENSIONS rates were added, or the next rate would leave RATE_RANGE."""
        if len(self.extension) >= MAX_EXTENSIONS:
            return False
        best = min(trials, key=lambda t: t["best_val_loss"])
        rate = beyond_edge([r for r, _ in self.points], best["learning_rate"])
        if rate is None:
            return False
        self.extension.append((rate, best["width_scale"]))
        return True


def _trials(study: Any, search: Search) -> list[dict[str, Any]]:
    """The finished trials at the search's points (a journal may hold others: a search with
    another grid in the same folder), by learning rate and width scale."""
    from optuna.trial import TrialState

    points = set(search.points)
    trials = [
        t.user_attrs
        for t in study.get_trials(deepcopy=False, states=(TrialState.COMPLETE,))
        if t.user_attrs and (t.params["learning_rate"], t.params["width_scale"]) in points
    ]
    return sorted(trials, key=lambda t: (t["learning_rate"], t["width_scale"]))


def _summary(spec: RunSpec, dataset: Any, base: Any, study: Any, search: Search) -> dict[str, Any]:
    trials = _trials(study, search)
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
        "grid": [{"learning_rate": r, "width_scale": s} for r, s in search.grid],
        "extended_rates": [rate for rate, _ in search.extension],
        "trials": trials,
        "complete": len(trials) == len(set(search.points)),
        "best": best,
        "best_on_edge": None if best is None else on_edge(trials, best),
        "git_commit": git_commit(),
    }

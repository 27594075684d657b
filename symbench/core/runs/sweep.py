"""Sweeps: a grid of runs that skips finished records, so an interrupted sweep resumes.

A run is finished when a record at its path (named by its key: dataset, preset, split, model,
variant, backend, protocol, the matched parameter count when set, seed) validates, matches
its seal and holds the requested configuration: the same dataset content, evaluators and
training configuration too (`identity.record_state`).
A record of another configuration there is never counted as finished: the sweep refuses
before any run starts, naming the first difference, unless the runs say `overwrite`, and then
they run again and replace those records. A record that cannot be trusted (corrupt, edited,
schema 1) is redone; records are written atomically, so a run killed half-way leaves none and
is simply redone. Datasets are made (or loaded) once each before the records are compared,
and so are the datasets the runs' evaluators declare trainings on (the closed loop's noisy
variant), with all of the sweep's workers, so parallel runs never race to generate them.
Local workers exit with the sweep, however it ends (`processes`); Ctrl-C reports how many
runs have records, counted on disk. A worker that dies (killed for memory) costs only the runs
it and its pool had under way: they run again at the end, one at a time, and a run that dies
even alone is named in the error, after every other run has finished. Each worker process
makes one run and ends, so memory a run leaves behind never adds up (measured at 7a8d9fb,
whose workers made one run after another: 12 GB in a worker on magneto).
"""

from __future__ import annotations

import itertools
from collections.abc import Callable, Sequence
from dataclasses import replace

from symbench.core.common.errors import SymbenchError
from symbench.core.common.processes import WorkerDied, run_each
from symbench.core.runs import ray_executor
from symbench.core.runs.identity import record_state, refusal
from symbench.core.runs.planning import declared_datasets
from symbench.core.runs.run_config import check_names
from symbench.core.runs.runner import run
from symbench.core.runs.spec import RunSpec, ensure_dataset, resolve_robot


def plan(
    models: Sequence[str],
    robots: Sequence[str],
    splits: Sequence[str],
    seeds: Sequence[int],
    backends: Sequence[str],
    base: RunSpec,
    datasets: Sequence[str] = (),
) -> list[RunSpec]:
    """Every combination, in a fixed order: the robots' standard datasets of `base.preset`,
    then `datasets` (cached ids, each run on its own robot); names are checked before
    anything runs."""
    data = [(r, None) for r in robots] + [(resolve_robot(None, d), d) for d in datasets]
    specs = [
        replace(base, model=m, robot=r, dataset=d, split=s, seed=seed, backend=b)
        for (r, d), s, m, b, seed in itertools.product(data, splits, models, backends, seeds)
    ]
    for spec in specs:
        check_names(spec)
    return specs


def finished(spec: RunSpec, content_hash: str | None = None) -> bool:
    """A valid record of this configuration (on data of `content_hash`, when given) exists."""
    return record_state(spec, content_hash)[0] == "same"


def _run_quietly(spec: RunSpec) -> str:
    """One run of a sweep, on the one process the sweep gives it (its trainings one after
    the other: the sweep's workers are the parallelism)."""
    run(replace(spec, progress=False, workers=1))
    return spec.key()


def sweep(
    specs: list[RunSpec],
    workers: int = 1,
    executor: str = "local",
    address: str | None = None,
    report: Callable[[str], None] = print,
) -> list[str]:
    """Run the unfinished specs, at most `workers` at once locally; returns the keys that ran.
    Refuses, before anything runs, when a record of another configuration is at the path of a
    spec that does not say `overwrite`."""
    if executor not in ("local", "ray"):
        raise SymbenchError(f"unknown executor '{executor}' (local, ray)")
    if workers < 1:
        raise SymbenchError(f"workers must be at least 1, got {workers}")
    datasets = {s.dataset_id: ensure_dataset(s) for s in {s.dataset_id: s for s in specs}.values()}
    hashes = {did: dataset.content_hash for did, dataset in datasets.items()}
    states = [(s, *record_state(s, hashes[s.dataset_id])) for s in specs]
    refused = [(s, why) for s, state, why in states if state == "different" and not s.overwrite]
    if refused:
        raise refusal(*refused[0], more=len(refused) - 1)
    todo = [s for s, state, _ in states if state != "same"]
    declared = {did: s for s in todo for did in declared_datasets(s, datasets[s.dataset_id])}
    for did, s in declared.items():
        ensure_dataset(replace(s, dataset=did, workers=workers))
    report(
        f"{len(specs) - len(todo)} of {len(specs)} runs already have records; {len(todo)} to run"
    )
    for s, state, why in states:
        if state == "different":
            report(f"replacing {s.record_path} (--overwrite): {why}")
        elif state == "unreadable":
            report(f"running again: {why}")
    ray = ray_executor.connect(address) if executor == "ray" and todo else None
    done: list[str] = []

    def finish(key: str) -> None:
        done.append(key)
        report(f"finished {key}")

    try:
        if ray is not None:
            return ray_executor.run_all(ray, _run_quietly, todo, report)
        if workers == 1:
            for spec in todo:
                finish(_run_quietly(spec))
        else:
            run_each(_run_quietly, todo, workers, finish, one_each=True)
    except WorkerDied as exc:
        keys = ", ".join(spec.key() for spec in exc.items)
        raise SymbenchError(
            f"a worker process died running {keys}, even alone (out of memory?); every "
            "other run finished; run the same command again to retry"
        ) from None
    except KeyboardInterrupt:
        have = sum(finished(s, hashes[s.dataset_id]) for s in specs)
        raise SymbenchError(
            f"interrupted with {have} of {len(specs)} runs finished; run the "
            "same command again to resume"
        ) from None
    return done

"""Sweeps: a grid of runs that skips finished records, so an interrupted sweep resumes.

A run is finished when its result record exists, validates and matches its seal (a
schema-1 record is redone); records are written
atomically, so a run killed half-way leaves none and is simply redone. Datasets are made
once per robot before the runs start, so parallel runs never race to generate them. Local
workers exit with the sweep, however it ends (`processes`); Ctrl-C reports how many runs
have records, counted on disk.
"""

from __future__ import annotations

import itertools
from collections.abc import Callable, Sequence
from dataclasses import replace

from symbench.core.common.errors import SymbenchError
from symbench.core.common.processes import run_each
from symbench.core.runs import ray_executor
from symbench.core.runs.results import read_record
from symbench.core.runs.runner import RunSpec, check_names, ensure_dataset, run


def plan(
    models: Sequence[str],
    robots: Sequence[str],
    splits: Sequence[str],
    seeds: Sequence[int],
    backends: Sequence[str],
    base: RunSpec,
) -> list[RunSpec]:
    """Every combination, in a fixed order; names are checked before anything runs."""
    specs = [
        replace(base, model=m, robot=r, split=s, seed=seed, backend=b)
        for r, s, m, b, seed in itertools.product(robots, splits, models, backends, seeds)
    ]
    for spec in specs:
        check_names(spec)
    return specs


def finished(spec: RunSpec) -> bool:
    """A valid record exists; a corrupt one counts as unfinished and will be rewritten."""
    if not spec.record_path.is_file():
        return False
    try:
        read_record(spec.record_path)
    except SymbenchError:
        return False
    return True


def _run_quietly(spec: RunSpec) -> str:
    run(replace(spec, progress=False))
    return spec.key()


def sweep(
    specs: list[RunSpec],
    workers: int = 1,
    executor: str = "local",
    address: str | None = None,
    report: Callable[[str], None] = print,
) -> list[str]:
    """Run the unfinished specs, at most `workers` at once locally; returns the keys that ran."""
    if executor not in ("local", "ray"):
        raise SymbenchError(f"unknown executor '{executor}' (local, ray)")
    if workers < 1:
        raise SymbenchError(f"workers must be at least 1, got {workers}")
    todo = [s for s in specs if not finished(s)]
    report(
        f"{len(specs) - len(todo)} of {len(specs)} runs already have records; {len(todo)} to run"
    )
    ray = ray_executor.connect(address) if executor == "ray" and todo else None
    for robot_spec in {(s.robot, s.preset): s for s in todo}.values():
        ensure_dataset(robot_spec)
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
            run_each(_run_quietly, todo, workers, finish)
    except KeyboardInterrupt:
        have = sum(finished(s) for s in specs)
        raise SymbenchError(
            f"interrupted with {have} of {len(specs)} runs finished; run the "
            "same command again to resume"
        ) from None
    return done

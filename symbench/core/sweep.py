"""Sweeps: a grid of runs that skips finished records, so an interrupted sweep resumes.

A run is finished when its result record exists, validates and matches its seal (a
schema-1 record is redone); records are written
atomically, so a run killed half-way leaves none and is simply redone. Datasets are made
once per robot before the runs start, so parallel runs never race to generate them.
"""

from __future__ import annotations

import itertools
import os
from collections.abc import Callable, Sequence
from dataclasses import replace

from symbench.core.errors import SymbenchError
from symbench.core.results import read_record
from symbench.core.runner import RunSpec, check_names, ensure_dataset, run


def plan(models: Sequence[str], robots: Sequence[str], splits: Sequence[str],
         seeds: Sequence[int], backends: Sequence[str], base: RunSpec) -> list[RunSpec]:
    """Every combination, in a fixed order; names are checked before anything runs."""
    specs = [replace(base, model=m, robot=r, split=s, seed=seed, backend=b)
             for r, s, m, b, seed in itertools.product(robots, splits, models, backends, seeds)]
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


def sweep(specs: list[RunSpec], workers: int = 1, executor: str = "local",
          address: str | None = None, report: Callable[[str], None] = print) -> list[str]:
    """Run the unfinished specs; returns the keys that ran."""
    if executor not in ("local", "ray"):
        raise SymbenchError(f"unknown executor '{executor}' (local, ray)")
    todo = [s for s in specs if not finished(s)]
    report(f"{len(specs) - len(todo)} of {len(specs)} runs already have records; {len(todo)} to run")
    for robot_spec in {(s.robot, s.preset): s for s in todo}.values():
        ensure_dataset(robot_spec)
    if executor == "ray":
        return _sweep_ray(todo, address, report)
    if workers <= 1:
        done = []
        for spec in todo:
            done.append(_run_quietly(spec))
            report(f"finished {spec.key()}")
        return done
    import multiprocessing
    from concurrent.futures import ProcessPoolExecutor, as_completed

    done = []
    with ProcessPoolExecutor(workers, mp_context=multiprocessing.get_context("spawn")) as pool:
        for future in as_completed([pool.submit(_run_quietly, s) for s in todo]):
            done.append(future.result())
            report(f"finished {done[-1]}")
    return done


def _sweep_ray(todo: list[RunSpec], address: str | None, report: Callable[[str], None]) -> list[str]:
    try:
        import ray
    except ImportError:
        raise SymbenchError("--executor ray needs Ray: pip install -c constraints.txt "
                            "'symbench[ray]'") from None
    # workers see the same cache and headless rendering as this process
    env = {k: os.environ[k] for k in ("SYMBENCH_HOME", "MUJOCO_GL") if k in os.environ}
    ray.init(address=address, ignore_reinit_error=True, log_to_driver=False,
             include_dashboard=False, runtime_env={"env_vars": env})
    remote = ray.remote(num_cpus=1)(_run_quietly)
    pending = {remote.remote(s): s for s in todo}
    done = []
    while pending:
        ready, _ = ray.wait(list(pending), num_returns=1)
        for ref in ready:
            done.append(ray.get(ref))
            pending.pop(ref)
            report(f"finished {done[-1]}")
    return done


"""`symbench data generate`: simulate a preset's scenario grid into a cached dataset.

Each trajectory is simulated in a worker process and written (Parquet, then a small record
JSON) the moment it finishes, both atomically; metadata.json is written last. An
interrupted run therefore resumes: a trajectory whose record matches the scenario, the
robot spec and the library versions, and whose file matches its SHA-256, is kept; the rest
is simulated again. A trajectory in which the robot detaches, or the simulator stops with a
SymbenchError (e.g. an infeasible controller QP), is recorded as failed and left out.
Simulation is deterministic, so the files and the content hash are too.
"""

from __future__ import annotations

import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from symbench.core.common.errors import SymbenchError
from symbench.core.common.hashing import sha256_file
from symbench.core.common.jsonfile import read_json
from symbench.core.common.processes import WorkerDied, run_each
from symbench.core.config.presets import RECORD_PERIOD, dataset_id, preset
from symbench.core.data.dataset import Dataset, load_dataset
from symbench.core.data.generation.determinism import (
    numerics_problems,
    pinned_worker_environment,
    require_pinned_numerics,
)
from symbench.core.data.storage.columns import check_flags
from symbench.core.data.storage.files import atomic_write_json, write_trajectory
from symbench.core.data.storage.metadata import (
    METADATA,
    dataset_dir,
    library_versions,
    write_metadata,
)
from symbench.core.robot.specs import load_robot
from symbench.core.sim.raw import SCHEMA_VERSION, validate_raw
from symbench.core.sim.scene.scenario import Scenario

Simulator = Callable[..., Any]  # (scenario, record_period=...) -> Rollout


@dataclass(frozen=True)
class Task:
    index: int
    scenario: dict[str, Any]
    root: Path
    n_legs: int
    key: dict[str, Any]  # what a finished record must match to be reused
    simulator: Simulator


@dataclass(frozen=True)
class GenerationReport:
    dataset_id: str
    root: Path
    n_trajectories: int
    n_failed: int
    n_samples: int
    n_simulated: int  # this run; the others were kept from an earlier run
    seconds: float
    content_hash: str
    failures: list[dict[str, Any]]


def default_simulator() -> Simulator:
    try:
        from symbench.core.sim.climb.rollout import simulate
    except ImportError as exc:
        raise SymbenchError(
            f"the simulator is not available ({exc}); "
            "symbench.core.sim.climb.rollout.simulate is needed to generate data"
        ) from None
    return simulate


def _is_real_simulator(sim: Simulator) -> bool:
    """Only the real simulator needs pinned numerics (named, not imported, so that asking
    does not load the simulator); tests' stand-ins run anywhere."""
    return (
        f"{getattr(sim, '__module__', '')}.{getattr(sim, '__qualname__', '')}"
        == "symbench.core.sim.climb.rollout.simulate"
    )


def record_path(root: Path, index: int) -> Path:
    return root / "records" / f"{index:05d}.json"


def trajectory_file(index: int) -> str:
    return f"trajectories/{index:05d}.parquet"


def run_task(task: Task) -> dict[str, Any]:
    """Simulate one scenario, write its file and record; return the record."""
    if _is_real_simulator(task.simulator):
        require_pinned_numerics()
    record: dict[str, Any] = {"id": task.index, "scenario": task.scenario, "key": task.key}
    try:
        rollout = task.simulator(
            Scenario.from_dict(task.scenario), record_period=task.key["record_period_s"]
        )
    except SymbenchError as exc:  # e.g. the controller found no feasible torques
        rollout = None
        record.update(status="failed", failure=f"simulation stopped: {exc}")
    if rollout is not None and not rollout.attached:
        record.update(status="failed", failure=rollout.failure or "the robot detached")
    elif rollout is not None:
        source = f"trajectory {task.index} ({task.scenario})"
        n_steps = validate_raw(rollout.arrays, task.n_legs, source)
        check_flags(rollout.arrays, source)
        if n_steps < 2:
            raise SymbenchError(f"{source}: {n_steps} recorded step(s), at least 2 are needed")
        sha = write_trajectory(task.root / trajectory_file(task.index), rollout.arrays, task.n_legs)
        record.update(status="ok", file=trajectory_file(task.index), sha256=sha, n_steps=n_steps)
    atomic_write_json(record_path(task.root, task.index), record)
    return record


def finished_record(task: Task) -> dict[str, Any] | None:
    """The record of an earlier run if it is still valid for `task`, else None."""
    path = record_path(task.root, task.index)
    if not path.is_file():
        return None
    try:
        record = read_json(path, "generation record")
    except SymbenchError:
        return None
    if (
        not isinstance(record, dict)
        or record.get("id") != task.index
        or record.get("scenario") != task.scenario
        or record.get("key") != task.key
    ):
        return None
    if record.get("status") == "ok":
        file_named = record.get("file") == trajectory_file(task.index)
        if not file_named or not isinstance(record.get("n_steps"), int):
            return None
        file = task.root / record["file"]
        if not file.is_file() or sha256_file(file) != record.get("sha256"):
            return None
    elif record.get("status") != "failed" or not isinstance(record.get("failure"), str):
        return None
    return record


def _run_all(
    tasks: Sequence[Task], workers: int, on_done: Callable[[dict], None], in_process: bool
) -> None:
    if in_process:
        for task in tasks:
            on_done(run_task(task))
        return
    run_each(run_task, tasks, workers, on_done, environment=pinned_worker_environment)


def generate(
    robot: str,
    preset_name: str = "small",
    workers: int = 1,
    simulator: Simulator | None = None,
    show_progress: bool = True,
    scenarios: Sequence[Scenario] | None = None,
    id_override: str | None = None,
    repair_command: str | None = None,
) -> GenerationReport:
    """Generate (or resume) the dataset of `preset_name` for `robot` in the cache.

    `scenarios` and `id_override` replace the preset's grid and id (tests use tiny grids;
    `symbench data symmetry` its constructed pairs, which name their own
    `repair_command`).
    The real simulator runs in spawned worker processes with pinned numerics (see
    symbench.core.data.generation.determinism), even for workers=1 unless this process is pinned: a
    script calling this needs the usual `if __name__ == "__main__":` guard.
    """
    spec = load_robot(robot)
    grid = preset(preset_name)
    did = id_override or dataset_id(robot, preset_name)
    order = spec.group.rotation_order
    scenarios = (
        list(scenarios) if scenarios is not None else grid.scenarios(robot, spec.n_legs, order)
    )
    root = dataset_dir(did)
    key = {
        "raw_schema_version": SCHEMA_VERSION,
        "robot_spec_hash": spec.spec_hash(),
        "record_period_s": RECORD_PERIOD,
        "versions": library_versions(),
    }
    sim = simulator or default_simulator()
    # the real simulator runs in this process only if its numerics here are pinned
    in_process = workers <= 1 and (not _is_real_simulator(sim) or not numerics_problems())
    tasks = [Task(i, s.to_dict(), root, spec.n_legs, key, sim) for i, s in enumerate(scenarios)]
    records: dict[int, dict[str, Any]] = {}
    for task in tasks:
        if (rec := finished_record(task)) is not None:
            records[task.index] = rec
    todo = [t for t in tasks if t.index not in records]

    start = time.perf_counter()
    failed_before = sum(r["status"] != "ok" for r in records.values())
    with ProgressBar(show_progress, len(tasks), len(records), failed_before, did) as advance:

        def on_done(rec: dict[str, Any]) -> None:
            records[rec["id"]] = rec
            advance(rec)

        try:
            _run_all(todo, workers, on_done, in_process)
        except KeyboardInterrupt:
            # counted on disk: work the pool finished while shutting down is not in `records`
            done = sum(finished_record(task) is not None for task in tasks)
            raise SymbenchError(
                f"interrupted with {done} of {len(tasks)} trajectories "
                "done; run the same command again to resume"
            ) from None
        except WorkerDied as exc:
            raise SymbenchError(
                f"a worker process died on {len(exc.items)} trajectories, even run alone, "
                f"with {len(records)} of {len(tasks)} done; run again to resume (a script "
                "that calls generate() needs an "
                "`if __name__ == '__main__':` guard)"
            ) from None
    seconds = time.perf_counter() - start
    failed = sum(r["status"] != "ok" for r in records.values())
    if id_override is None and failed > grid.max_failed_share * len(tasks):
        raise SymbenchError(
            f"{did}: the expert failed {failed} of {len(tasks)} climbs, more than the "
            f"{grid.max_failed_share:.0%} a standard dataset allows; its distribution asks "
            "for slopes or steps the controller does not climb reliably (the finished "
            "trajectories stay in the cache)"
        )
    grid_doc = grid.grid(order) if id_override is None else {"scenarios": len(tasks)}
    meta = _write_dataset(
        root,
        did,
        robot,
        grid.name,
        spec.n_legs,
        key,
        grid_doc,
        [records[i] for i in range(len(tasks))],
        repair_command or f"symbench data generate --robot {robot} --preset {grid.name}",
    )
    return GenerationReport(
        did,
        root,
        len(meta["trajectories"]),
        len(meta["failures"]),
        meta["n_samples"],
        len(todo),
        seconds,
        meta["content_hash"],
        meta["failures"],
    )


def _write_dataset(
    root: Path,
    did: str,
    robot: str,
    preset_name: str,
    n_legs: int,
    key: dict[str, Any],
    grid_doc: dict[str, Any],
    records: list[dict[str, Any]],
    repair_command: str,
) -> dict[str, Any]:
    """metadata.json from the records in grid order: kept trajectories, then failures."""
    ok = [
        {k: r[k] for k in ("id", "file", "sha256", "n_steps", "scenario")}
        for r in records
        if r["status"] == "ok"
    ]
    failures = [
        {k: r[k] for k in ("id", "scenario", "failure")} for r in records if r["status"] != "ok"
    ]
    return write_metadata(
        root,
        {
            "id": did,
            "source": "generated",
            "robot": robot,
            "n_legs": n_legs,
            "robot_spec_hash": key["robot_spec_hash"],
            "raw_schema_version": SCHEMA_VERSION,
            "record_period_s": RECORD_PERIOD,
            "versions": key["versions"],
            "preset": preset_name,
            "scenario_grid": grid_doc,
            "trajectories": ok,
            "failures": failures,
            "n_samples": sum(r["n_steps"] - 1 for r in ok),
            # hashed with the rest, so an earlier version's dataset keeps its name, not its key
            "repair_command": repair_command,
        },
    )


class ProgressBar:
    """A rich progress bar over trajectories (or nothing), counting failures as they come."""

    def __init__(self, show: bool, total: int, done: int, failed: int, label: str):
        self.show, self.total, self.done, self.label = show, total, done, label
        self.failed = failed

    def __enter__(self) -> Callable[[dict], None]:
        if not self.show:
            return lambda rec: None
        from rich.progress import (
            BarColumn,
            MofNCompleteColumn,
            Progress,
            TextColumn,
            TimeElapsedColumn,
            TimeRemainingColumn,
        )

        self.bar = Progress(
            TextColumn("{task.description}"),
            BarColumn(),
            MofNCompleteColumn(),
            TimeElapsedColumn(),
            TimeRemainingColumn(),
        )
        self.bar.start()
        self.task = self.bar.add_task(self.label, total=self.total, completed=self.done)
        return self.advance

    def advance(self, rec: dict) -> None:
        self.failed += rec["status"] != "ok"
        suffix = f" ({self.failed} failed)" if self.failed else ""
        self.bar.update(self.task, advance=1, description=self.label + suffix)

    def __exit__(self, *exc: object) -> None:
        if self.show:
            self.bar.stop()


def ensure_dataset(
    robot: str, preset_name: str = "small", workers: int = 2, show_progress: bool = True
) -> Dataset:
    """The preset's dataset, generated first when it is missing or its robot spec changed."""
    did = dataset_id(robot, preset_name)
    if (dataset_dir(did) / METADATA).is_file():
        dataset = load_dataset(did)
        if dataset.metadata["robot_spec_hash"] == load_robot(robot).spec_hash():
            return dataset
    generate(robot, preset_name, workers, show_progress=show_progress)
    return load_dataset(did)

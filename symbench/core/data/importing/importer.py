"""`symbench data import` / `export`: external robot logs <-> cached datasets.

An import folder holds one Parquet or npz file per trajectory and `import.json`:

    {"robot": "hexa", "record_period_s": 0.006,
     "trajectories": [{"file": "run1.parquet", "scenario": {"heading_deg": 0, "yaw_deg": 30}}]}

Parquet files carry one scalar column per component (`t`, `base_quat.w`, `q.leg0.coxa`,
`contact.leg0`, ... see symbench.core.data.storage.columns); npz files carry one array per raw
column shaped (T, ...) as in symbench/core/sim/raw.py. `trajectories` may be left out: then
every *.parquet and *.npz file of the folder is imported, in name order. Every file is
checked (columns, lengths, leg count, NaN, values beyond float32, flags, sampling period)
before anything is written, and the imported dataset is stored exactly like a generated one:
built in a hidden staging folder and renamed into place once complete, so a failed import
(even with --force) leaves the cache as it was.
"""

from __future__ import annotations

import io
import shutil
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from symbench.core.common.atomic import replace_folder, staging_folder, write_bytes_atomic
from symbench.core.common.errors import SymbenchError, first_of
from symbench.core.config.presets import RECORD_PERIOD
from symbench.core.data.dataset import Dataset, load_dataset
from symbench.core.data.importing.derive import DERIVABLE, resample, resample_plan
from symbench.core.data.importing.logs import check_trajectory, complete_columns, read_log_file
from symbench.core.data.importing.manifest import IMPORT_JSON, read_manifest
from symbench.core.data.storage.files import atomic_write_json, read_trajectory, write_trajectory
from symbench.core.data.storage.metadata import (
    METADATA,
    dataset_dir,
    library_versions,
    write_metadata,
)
from symbench.core.data.storage.scenario_fields import SCENARIO_KEYS
from symbench.core.sim.raw import SCHEMA_VERSION


@dataclass
class FilePlan:
    """What the import does to one file, and why."""

    file: str
    rows_in: int
    rows_out: int
    derived: tuple[str, ...]  # raw columns computed from others
    dropped: tuple[str, ...]  # columns of the file that are not kept
    resampled: str | None  # how the rows were brought to the record period


@dataclass
class ImportPlan:
    """Everything `symbench data import` will do, before it writes anything (`--dry-run`)."""

    folder: Path
    dataset_id: str
    robot: str
    log_period_s: float
    record_period_s: float
    physics_step_s: float
    base_frame: str
    unknown: tuple[str, ...]
    provenance: dict[str, Any]
    files: list[FilePlan] = field(default_factory=list)

    def lines(self) -> list[str]:
        n = len(self.files)
        out = [
            f"import {n} trajector{'y' if n == 1 else 'ies'} of {self.folder} as "
            f"'{self.dataset_id}' (robot {self.robot}): "
            f"{sum(f.rows_in for f in self.files)} rows in, "
            f"{sum(f.rows_out for f in self.files)} rows kept"
        ]
        for column, source in DERIVABLE.items():
            files = [f.file for f in self.files if column in f.derived]
            if files:
                out.append(
                    f"derive {column} from {source} in {_count(files, n)}: the log has no "
                    f"{column}; ({source}(t + h) - {source}(t)) / h with h = "
                    f"{self.physics_step_s:g} s, the robot's physics step, as the generator "
                    "records it, estimated from the log's rows (finite differences, no filter)"
                )
        resampled = [f for f in self.files if f.resampled]
        if resampled:
            out.append(
                f"resample {_count([f.file for f in resampled], n)}: "
                f"{resampled[0].resampled}; record period {self.log_period_s:g} s in "
                f"{IMPORT_JSON}, the robot's is {self.record_period_s:g} s (the `next` "
                "variant predicts one record period ahead)"
            )
        else:
            out.append(
                f"keep every row: the log's period {self.log_period_s:g} s is the robot's "
                f"record period {self.record_period_s:g} s"
            )
        if self.base_frame == "body":
            out.append(
                "rotate base_linvel, base_angvel (and base_linacc when given) from the base "
                f"frame to the world frame by base_quat: {IMPORT_JSON} says base_frame = body"
            )
        for name in self.unknown:
            out.append(
                f"store {name} as 0 and mark it unknown ({IMPORT_JSON} 'unknown'): every view "
                f"uses {name}, so training on this dataset is refused with that reason"
            )
        dropped: dict[str, list[str]] = {}
        for f in self.files:
            for column in f.dropped:
                dropped.setdefault(column, []).append(f.file)
        for column, files in dropped.items():
            why = (
                f"declared unknown in {IMPORT_JSON}"
                if column.split(".")[0] in self.unknown
                else "not a raw column (docs/data-format.md)"
            )
            out.append(f"drop column {column} of {_count(files, n)}: {why}")
        if self.provenance:
            shown = ", ".join(f"{k} = {v}" for k, v in sorted(self.provenance.items()))
            out.append(f"keep as provenance (shown by `symbench data info`): {shown}")
        return out


def _count(files: list[str], total: int) -> str:
    if len(files) == total and total > 1:
        return f"all {total} files"
    return first_of(files, 3)


Prepared = tuple[ImportPlan, list[tuple[dict[str, np.ndarray], int, dict[str, Any], str]]]


def prepare_import(folder: Path, dataset_id: str) -> Prepared:
    """Read and check every file of `folder` and bring it to the stored form; nothing is
    written. The plan says what was derived, dropped and resampled, and why."""
    from symbench.core.robot.specs import load_robot

    folder = Path(folder).resolve()
    manifest, entries = read_manifest(folder)
    robot = load_robot(manifest.robot)
    physics_step = robot.control.timestep
    try:
        resample_plan(manifest.record_period_s, RECORD_PERIOD)  # refuses a longer period
    except SymbenchError as error:  # the file to fix, named
        raise SymbenchError(f"{folder / IMPORT_JSON}: {error}") from None
    plan = ImportPlan(
        folder,
        dataset_id,
        robot.name,
        manifest.record_period_s,
        RECORD_PERIOD,
        physics_step,
        manifest.base_frame,
        tuple(manifest.unknown),
        dict(manifest.provenance),
    )
    loaded = []
    for entry in entries:
        path = folder / entry.file
        if not path.is_file():
            raise SymbenchError(f"{path}: listed in {IMPORT_JSON} but does not exist")
        arrays, extra = read_log_file(path, robot.n_legs, robot.name)
        arrays, derived, dropped = complete_columns(
            arrays, manifest, robot.n_legs, physics_step, str(path)
        )
        n_in = check_trajectory(arrays, robot.n_legs, manifest.record_period_s, str(path))
        arrays, how = resample(arrays, manifest.record_period_s, RECORD_PERIOD)
        n = len(arrays["t"])
        if n < 2:
            raise SymbenchError(
                f"{path}: {n} step(s) at the record period {RECORD_PERIOD:g} s; a "
                "trajectory needs at least 2"
            )
        plan.files.append(
            FilePlan(entry.file, n_in, n, tuple(derived), tuple(dropped + extra), how)
        )
        scenario = {"robot": robot.name, **entry.scenario.model_dump()}
        loaded.append((arrays, n, scenario, entry.file))
    return plan, loaded


def import_logs(
    folder: Path, dataset_id: str, force: bool = False, prepared: Prepared | None = None
) -> Dataset:
    """Check every file of `folder`, then store them as dataset `dataset_id` (a folder without
    metadata.json there is an unfinished import or generation, and is replaced); `prepared`:
    what `prepare_import` already made of the folder."""
    from symbench.core.robot.specs import load_robot

    folder = Path(folder).resolve()
    root = dataset_dir(dataset_id)
    if (root / METADATA).is_file() and not force:
        raise SymbenchError(
            f"dataset '{dataset_id}' already exists ({root}); pass --force to replace it"
        )
    plan, loaded = prepared or prepare_import(folder, dataset_id)
    robot = load_robot(plan.robot)
    staging = staging_folder(root)
    try:
        records = []
        for i, (arrays, n, scenario, source) in enumerate(loaded):
            file = f"trajectories/{i:05d}.parquet"
            sha = write_trajectory(staging / file, arrays, robot.n_legs)
            records.append(
                {
                    "id": i,
                    "file": file,
                    "sha256": sha,
                    "n_steps": n,
                    "scenario": scenario,
                    "source_file": source,
                }
            )
        write_metadata(
            staging,
            {
                "id": dataset_id,
                "source": "imported",
                "imported_from": str(folder),
                "robot": robot.name,
                "n_legs": robot.n_legs,
                "robot_spec_hash": robot.spec_hash(),
                "raw_schema_version": SCHEMA_VERSION,
                "record_period_s": RECORD_PERIOD,
                "versions": library_versions(),
                "trajectories": records,
                "failures": [],
                "n_samples": sum(n - 1 for _, n, _, _ in loaded),
                "unknown_columns": list(plan.unknown),
                "provenance": plan.provenance,
                "import": {
                    "log_period_s": plan.log_period_s,
                    "base_frame": plan.base_frame,
                    "physics_step_s": plan.physics_step_s,
                    "steps": plan.lines()[1:],
                },
                "repair_command": f"symbench data import {folder} --id {dataset_id} --force",
            },
        )
        replace_folder(staging, root)
    finally:
        shutil.rmtree(staging, ignore_errors=True)  # gone already when the import succeeded
    return load_dataset(dataset_id)


def export_dataset(dataset: Dataset, folder: Path, fmt: str = "parquet") -> Path:
    """Write `dataset` in the import format (one file per trajectory plus import.json)."""
    if fmt not in ("parquet", "npz"):
        raise SymbenchError(f"export format must be parquet or npz, got '{fmt}'")
    folder = Path(folder)
    entries = []
    for rec in dataset.metadata["trajectories"]:
        arrays = read_trajectory(dataset.root / rec["file"], dataset.n_legs)
        name = f"trajectory-{rec['id']:05d}.{fmt}"
        if fmt == "parquet":
            write_trajectory(folder / name, arrays, dataset.n_legs)
        else:
            buf = io.BytesIO()
            np.savez(buf, **arrays)  # type: ignore[arg-type]  # numpy's stub misreads **kwargs
            write_bytes_atomic(folder / name, buf.getvalue())
        scenario = {
            k: v for k, v in rec["scenario"].items() if k in SCENARIO_KEYS and v is not None
        }
        entries.append({"file": name, "scenario": scenario})
    manifest: dict[str, Any] = {
        "robot": dataset.robot,
        "record_period_s": dataset.metadata["record_period_s"],
        "trajectories": entries,
    }
    if dataset.metadata.get("unknown_columns"):
        manifest["unknown"] = dataset.metadata["unknown_columns"]
    if dataset.metadata.get("provenance"):
        manifest["provenance"] = dataset.metadata["provenance"]
    atomic_write_json(folder / IMPORT_JSON, manifest)
    return folder

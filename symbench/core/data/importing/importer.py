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
import json
import shutil
import zipfile
import zlib
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from symbench.core.common.atomic import replace_folder, staging_folder, write_bytes_atomic
from symbench.core.common.errors import SymbenchError
from symbench.core.common.jsonfile import one_line
from symbench.core.config.presets import RECORD_PERIOD
from symbench.core.data.dataset import Dataset, load_dataset
from symbench.core.data.importing.derive import (
    DERIVABLE,
    UNKNOWABLE,
    body_to_world,
    derivative,
    resample,
    resample_plan,
)
from symbench.core.data.importing.manifest import IMPORT_JSON, ImportManifest, read_manifest
from symbench.core.data.storage.columns import check_flags, flat_names, legs_in
from symbench.core.data.storage.files import (
    atomic_write_json,
    read_columns,
    read_trajectory,
    write_trajectory,
)
from symbench.core.data.storage.metadata import (
    METADATA,
    dataset_dir,
    library_versions,
    write_metadata,
)
from symbench.core.data.storage.scenario_fields import SCENARIO_KEYS
from symbench.core.sim.raw import (
    COLUMN_NAMES,
    RAW_COLUMNS,
    SCHEMA_VERSION,
    column_shape,
    validate_raw,
)

PERIOD_TOLERANCE = 0.05  # relative deviation of any time step from record_period_s
LARGEST = float(np.finfo(np.float32).max)  # models compute in float32


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
    return ", ".join(files[:3]) + (f" and {len(files) - 3} more" if len(files) > 3 else "")


def _read_file(path: Path, n_legs: int, robot: str) -> tuple[dict[str, np.ndarray], list[str]]:
    """The raw columns one log file has, shaped, with the leg count and lengths checked; and
    the names of its other columns (dropped)."""
    if path.suffix == ".parquet":
        columns = read_columns(path)
        found = legs_in(list(columns))
        if found and found != n_legs:
            raise SymbenchError(
                f"{path}: has columns for {found} legs, robot '{robot}' has {n_legs}"
            )
        arrays, known = {}, set()
        for col in RAW_COLUMNS:
            names = flat_names(col, n_legs)
            known.update(names)
            have = [name in columns for name in names]
            if all(have):
                stacked = np.stack([np.asarray(columns[name]) for name in names], axis=-1)
                arrays[col.name] = stacked.reshape(len(stacked), *column_shape(col, n_legs))
            elif any(have):
                missing = [name for name, ok in zip(names, have, strict=True) if not ok]
                more = f" and {len(missing) - 5} more" if len(missing) > 5 else ""
                raise SymbenchError(f"{path}: missing column(s) {', '.join(missing[:5])}{more}")
        return arrays, sorted(set(columns) - known)
    try:
        with np.load(path, allow_pickle=False) as npz:
            arrays = {k: npz[k] for k in npz.files}
    except (OSError, ValueError, EOFError, zipfile.BadZipFile, zlib.error) as exc:
        raise SymbenchError(
            f"{path}: not a readable npz file without pickles "
            f"({one_line(exc) or type(exc).__name__})"
        ) from None
    extra = sorted(k for k in arrays if k not in COLUMN_NAMES)
    arrays = {k: v for k, v in arrays.items() if k in COLUMN_NAMES}
    q = arrays.get("q")
    if q is not None and q.ndim == 3 and q.shape[1] != n_legs:
        raise SymbenchError(f"{path}: 'q' has {q.shape[1]} legs, robot '{robot}' has {n_legs}")

    def steps(a: np.ndarray) -> str:
        return f"{np.shape(a)[0]} steps" if np.ndim(a) else "no time axis"

    if "t" in arrays:
        for name, a in arrays.items():
            if np.shape(a)[:1] != np.shape(arrays["t"])[:1]:
                raise SymbenchError(
                    f"{path}: column '{name}' has {steps(a)} (shape "
                    f"{np.shape(a)}), 't' has {steps(arrays['t'])}"
                )
    return arrays, extra


def _numeric(arrays: dict[str, np.ndarray], source: str) -> dict[str, np.ndarray]:
    """Every raw column as float64; a column of text or objects is named."""
    out = {}
    for name in COLUMN_NAMES:
        if name not in arrays:
            continue
        try:
            out[name] = np.asarray(arrays[name], dtype=np.float64)
        except (TypeError, ValueError):
            raise SymbenchError(
                f"{source}: column '{name}' is not numeric ({np.asarray(arrays[name]).dtype})"
            ) from None
    return out


def check_trajectory(arrays: dict[str, np.ndarray], n_legs: int, period: float, source: str) -> int:
    """Schema, finiteness, 0/1 flags and the sampling period; the number of steps."""
    arrays = _numeric(arrays, source)
    n = validate_raw(arrays, n_legs, source)
    if n < 2:
        raise SymbenchError(f"{source}: {n} step(s); a trajectory needs at least 2")
    for name, values in arrays.items():
        per_step = values.reshape(n, -1)
        huge = np.abs(per_step) > LARGEST
        if huge.any():
            step, column = np.argwhere(huge)[0]
            raise SymbenchError(
                f"{source}: column '{name}' holds {per_step[step, column]:g} at step "
                f"{step}, beyond float32 (±{LARGEST:.3g}), in which models compute"
            )
    check_flags(arrays, source)
    _check_period(arrays["t"], period, source)
    return n


def _check_period(t: np.ndarray, period: float, source: str) -> None:
    dt = np.diff(np.asarray(t, np.float64))
    if len(dt) and np.abs(dt - period).max() > PERIOD_TOLERANCE * period:
        raise SymbenchError(
            f"{source}: time steps range {dt.min():.6g}..{dt.max():.6g} s, but "
            f"{IMPORT_JSON} says record_period_s = {period:g}"
        )


def _complete(
    arrays: dict[str, np.ndarray],
    manifest: ImportManifest,
    n_legs: int,
    physics_step: float,
    source: str,
) -> tuple[dict[str, np.ndarray], list[str], list[str]]:
    """Every raw column at the log's rows: base vectors in the world frame, accelerations
    derived when missing, unknown columns as 0; with the derived and the dropped columns."""
    missing = [
        c for c in COLUMN_NAMES if c not in arrays and c not in DERIVABLE and c not in UNKNOWABLE
    ]
    if missing:
        raise SymbenchError(f"{source}: missing column(s) {', '.join(missing)}")
    absent = [c for c in UNKNOWABLE if c not in arrays and c not in manifest.unknown]
    if absent:
        raise SymbenchError(
            f"{source}: missing column(s) {', '.join(absent)}; if the log has no reliable "
            f'{absent[0]}, declare it in {IMPORT_JSON}: "unknown": {json.dumps(absent)}'
        )
    arrays = _numeric(arrays, source)
    n = len(arrays["t"])
    if n < 2:
        raise SymbenchError(f"{source}: {n} step(s); a trajectory needs at least 2")
    if not np.all(np.isfinite(arrays["t"])) or np.any(np.diff(arrays["t"]) <= 0):
        validate_raw({**_zeros_for_missing(arrays, n_legs), **arrays}, n_legs, source)
    _check_period(arrays["t"], manifest.record_period_s, source)
    if manifest.base_frame == "body":
        arrays = body_to_world(arrays)
    derived = []
    for column, source_column in DERIVABLE.items():
        if column not in arrays:
            arrays[column] = derivative(arrays["t"], arrays[source_column], physics_step)
            derived.append(column)
    dropped = []
    for column in manifest.unknown:
        if column in arrays:
            dropped.append(column)
        arrays[column] = np.zeros((n, n_legs))
    return arrays, derived, dropped


def _zeros_for_missing(arrays: dict[str, np.ndarray], n_legs: int) -> dict[str, np.ndarray]:
    n = len(arrays["t"])
    return {
        col.name: np.zeros((n, *column_shape(col, n_legs)))
        for col in RAW_COLUMNS
        if col.name not in arrays
    }


Prepared = tuple[ImportPlan, list[tuple[dict[str, np.ndarray], int, dict[str, Any], str]]]


def prepare_import(folder: Path, dataset_id: str) -> Prepared:
    """Read and check every file of `folder` and bring it to the stored form; nothing is
    written. The plan says what was derived, dropped and resampled, and why."""
    from symbench.core.robot.specs import load_robot

    folder = Path(folder).resolve()
    manifest, entries = read_manifest(folder)
    robot = load_robot(manifest.robot)
    physics_step = robot.control.timestep
    resample_plan(manifest.record_period_s, RECORD_PERIOD)  # refuses a longer period
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
        arrays, extra = _read_file(path, robot.n_legs, robot.name)
        arrays, derived, dropped = _complete(
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

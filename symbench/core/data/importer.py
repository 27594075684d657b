"""`symbench data import` / `export`: external robot logs <-> cached datasets.

An import folder holds one Parquet or npz file per trajectory and `import.json`:

    {"robot": "hexa", "record_period_s": 0.006,
     "trajectories": [{"file": "run1.parquet", "scenario": {"heading_deg": 0, "yaw_deg": 30}}]}

Parquet files carry one scalar column per component (`t`, `base_quat.w`, `q.leg0.coxa`,
`contact.leg0`, ... see symbench.core.data.columns); npz files carry one array per raw
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
import zipfile
import zlib
from pathlib import Path

import numpy as np

from symbench.core.common.atomic import replace_folder, staging_folder, write_bytes_atomic
from symbench.core.common.errors import SymbenchError
from symbench.core.common.jsonfile import one_line
from symbench.core.data.columns import check_flags, legs_in, unflatten
from symbench.core.data.dataset import Dataset, load_dataset
from symbench.core.data.import_manifest import IMPORT_JSON, read_manifest
from symbench.core.data.metadata import METADATA, dataset_dir, library_versions, write_metadata
from symbench.core.data.scenario_fields import SCENARIO_KEYS
from symbench.core.data.storage import (
    atomic_write_json,
    read_columns,
    read_trajectory,
    write_trajectory,
)
from symbench.core.sim.raw import COLUMN_NAMES, SCHEMA_VERSION, validate_raw

PERIOD_TOLERANCE = 0.05  # relative deviation of any time step from record_period_s
LARGEST = float(np.finfo(np.float32).max)  # models compute in float32


def _read_file(path: Path, n_legs: int, robot: str) -> dict[str, np.ndarray]:
    """Shaped raw arrays of one log file, with the leg count and lengths checked."""
    if path.suffix == ".parquet":
        columns = read_columns(path)
        found = legs_in(list(columns))
        if found and found != n_legs:
            raise SymbenchError(
                f"{path}: has columns for {found} legs, robot '{robot}' has {n_legs}"
            )
        return unflatten(columns, n_legs, str(path))
    try:
        with np.load(path, allow_pickle=False) as npz:
            arrays = {k: npz[k] for k in npz.files}
    except (OSError, ValueError, EOFError, zipfile.BadZipFile, zlib.error) as exc:
        raise SymbenchError(
            f"{path}: not a readable npz file without pickles "
            f"({one_line(exc) or type(exc).__name__})"
        ) from None
    missing = [c for c in COLUMN_NAMES if c not in arrays]
    if missing:
        raise SymbenchError(f"{path}: missing column(s) {', '.join(missing)}")
    q = arrays["q"]
    if q.ndim == 3 and q.shape[1] != n_legs:
        raise SymbenchError(f"{path}: 'q' has {q.shape[1]} legs, robot '{robot}' has {n_legs}")

    def steps(a: np.ndarray) -> str:
        return f"{np.shape(a)[0]} steps" if np.ndim(a) else "no time axis"

    for name in COLUMN_NAMES:
        if np.shape(arrays[name])[:1] != np.shape(arrays["t"])[:1]:
            raise SymbenchError(
                f"{path}: column '{name}' has {steps(arrays[name])} (shape "
                f"{np.shape(arrays[name])}), 't' has {steps(arrays['t'])}"
            )
    return arrays


def _numeric(arrays: dict[str, np.ndarray], source: str) -> dict[str, np.ndarray]:
    """Every raw column as float64; a column of text or objects is named."""
    out = {}
    for name in COLUMN_NAMES:
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
    dt = np.diff(np.asarray(arrays["t"], np.float64))
    if np.abs(dt - period).max() > PERIOD_TOLERANCE * period:
        raise SymbenchError(
            f"{source}: time steps range {dt.min():.6g}..{dt.max():.6g} s, but "
            f"{IMPORT_JSON} says record_period_s = {period:g}"
        )
    return n


def import_logs(folder: Path, dataset_id: str, force: bool = False) -> Dataset:
    """Check every file of `folder`, then store them as dataset `dataset_id` (a folder without
    metadata.json there is an unfinished import or generation, and is replaced)."""
    from symbench.core.robot.specs import load_robot

    folder = Path(folder).resolve()
    manifest, entries = read_manifest(folder)
    robot = load_robot(manifest.robot)
    root = dataset_dir(dataset_id)
    if (root / METADATA).is_file() and not force:
        raise SymbenchError(
            f"dataset '{dataset_id}' already exists ({root}); pass --force to replace it"
        )
    loaded = []
    for entry in entries:
        path = folder / entry.file
        if not path.is_file():
            raise SymbenchError(f"{path}: listed in {IMPORT_JSON} but does not exist")
        arrays = _read_file(path, robot.n_legs, robot.name)
        n = check_trajectory(arrays, robot.n_legs, manifest.record_period_s, str(path))
        loaded.append((arrays, n, {"robot": robot.name, **entry.scenario.model_dump()}, entry.file))
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
                "record_period_s": manifest.record_period_s,
                "versions": library_versions(),
                "trajectories": records,
                "failures": [],
                "n_samples": sum(n - 1 for _, n, _, _ in loaded),
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
    atomic_write_json(
        folder / IMPORT_JSON,
        {
            "robot": dataset.robot,
            "record_period_s": dataset.metadata["record_period_s"],
            "trajectories": entries,
        },
    )
    return folder

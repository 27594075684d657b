"""`symbench data import` / `export`: external robot logs <-> cached datasets.

An import folder holds one Parquet or npz file per trajectory and `import.json`:

    {"robot": "hexa", "record_period_s": 0.006,
     "trajectories": [{"file": "run1.parquet", "scenario": {"heading_deg": 0, "yaw_deg": 30}}]}

Parquet files carry one scalar column per component (`t`, `base_quat.w`, `q.leg0.coxa`,
`contact.leg0`, ... see symbench.core.data.columns); npz files carry one array per raw
column shaped (T, ...) as in symbench/core/raw.py. `trajectories` may be left out: then
every *.parquet and *.npz file of the folder is imported, in name order. Every file is
checked (columns, lengths, leg count, NaN, flags, sampling period) before anything is
written, and the imported dataset is stored exactly like a generated one.
"""

from __future__ import annotations

import io
from pathlib import Path
from typing import Any

import numpy as np

from symbench.core.atomic import write_bytes_atomic
from symbench.core.data.columns import check_flags, legs_in, unflatten
from symbench.core.data.dataset import Dataset, load_dataset
from symbench.core.data.metadata import dataset_dir, library_versions, write_metadata
from symbench.core.data.storage import (atomic_write_json, read_columns,
                                        read_json, read_trajectory, write_trajectory)
from symbench.core.errors import SymbenchError
from symbench.core.raw import COLUMN_NAMES, SCHEMA_VERSION, validate_raw
from symbench.core.scenario import Scenario

IMPORT_JSON = "import.json"
SUFFIXES = (".parquet", ".npz")
SCENARIO_KEYS = tuple(f for f in Scenario.__dataclass_fields__ if f != "robot")
PERIOD_TOLERANCE = 0.05  # relative deviation of any time step from record_period_s


def _read_file(path: Path, n_legs: int, robot: str) -> dict[str, np.ndarray]:
    """Shaped raw arrays of one log file, with the leg count and lengths checked."""
    if path.suffix == ".parquet":
        columns = read_columns(path)
        found = legs_in(list(columns))
        if found and found != n_legs:
            raise SymbenchError(f"{path}: has columns for {found} legs, robot '{robot}' has {n_legs}")
        return unflatten(columns, n_legs, str(path))
    try:
        with np.load(path, allow_pickle=False) as npz:
            arrays = {k: npz[k] for k in npz.files}
    except (OSError, ValueError) as exc:
        raise SymbenchError(f"{path}: not a readable npz file without pickles ({exc})") from None
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
            raise SymbenchError(f"{path}: column '{name}' has {steps(arrays[name])} (shape "
                                f"{np.shape(arrays[name])}), 't' has {steps(arrays['t'])}")
    return arrays


def _numeric(arrays: dict[str, np.ndarray], source: str) -> dict[str, np.ndarray]:
    """Every raw column as float64; a column of text or objects is named."""
    out = {}
    for name in COLUMN_NAMES:
        try:
            out[name] = np.asarray(arrays[name], dtype=np.float64)
        except (TypeError, ValueError):
            raise SymbenchError(f"{source}: column '{name}' is not numeric "
                                f"({np.asarray(arrays[name]).dtype})") from None
    return out


def check_trajectory(arrays: dict[str, np.ndarray], n_legs: int, period: float, source: str) -> int:
    """Schema, finiteness, 0/1 flags and the sampling period; the number of steps."""
    arrays = _numeric(arrays, source)
    n = validate_raw(arrays, n_legs, source)
    if n < 2:
        raise SymbenchError(f"{source}: {n} step(s); a trajectory needs at least 2")
    check_flags(arrays, source)
    dt = np.diff(np.asarray(arrays["t"], np.float64))
    if np.abs(dt - period).max() > PERIOD_TOLERANCE * period:
        raise SymbenchError(f"{source}: time steps range {dt.min():.6g}..{dt.max():.6g} s, but "
                            f"{IMPORT_JSON} says record_period_s = {period:g}")
    return n


def _manifest(folder: Path) -> tuple[dict[str, Any], list[dict[str, Any]]]:
    if not (folder / IMPORT_JSON).is_file():
        raise SymbenchError(f"{folder} has no {IMPORT_JSON} naming the robot and the record "
                            "period (see 'Importing a real robot's logs' in the README)")
    spec = read_json(folder / IMPORT_JSON, "import")
    if not isinstance(spec, dict):
        raise SymbenchError(f"{folder / IMPORT_JSON}: expected a JSON object")
    for key in ("robot", "record_period_s"):
        if key not in spec:
            raise SymbenchError(f"{folder / IMPORT_JSON}: missing '{key}'")
    period = spec["record_period_s"]
    if not isinstance(period, (int, float)) or not period > 0:
        raise SymbenchError(f"{folder / IMPORT_JSON}: record_period_s must be a positive number")
    entries = spec.get("trajectories")
    if entries is None:
        entries = [{"file": p.name} for p in sorted(folder.iterdir()) if p.suffix in SUFFIXES]
    if not entries:
        raise SymbenchError(f"{folder}: no *.parquet or *.npz trajectory files")
    for entry in entries:
        if not isinstance(entry, dict) or "file" not in entry:
            raise SymbenchError(f"{folder / IMPORT_JSON}: each trajectory needs a 'file'")
        unknown = sorted(set(entry.get("scenario", {})) - set(SCENARIO_KEYS))
        if unknown:
            raise SymbenchError(f"{folder / IMPORT_JSON}: {entry['file']}: unknown scenario "
                                f"field(s) {', '.join(unknown)} (known: {', '.join(SCENARIO_KEYS)})")
        if Path(entry["file"]).suffix not in SUFFIXES:
            raise SymbenchError(f"{folder / IMPORT_JSON}: {entry['file']} is neither .parquet nor .npz")
    return spec, entries


def import_logs(folder: Path, dataset_id: str, force: bool = False) -> Dataset:
    """Check every file of `folder`, then store them as dataset `dataset_id`."""
    from symbench.core.robots import load_robot

    folder = Path(folder).resolve()
    spec_json, entries = _manifest(folder)
    robot = load_robot(str(spec_json["robot"]))
    period = float(spec_json["record_period_s"])
    root = dataset_dir(dataset_id)
    if root.exists() and not force:
        raise SymbenchError(f"dataset '{dataset_id}' already exists ({root}); pass --force to replace it")
    loaded = []
    for entry in entries:
        path = folder / entry["file"]
        if not path.is_file():
            raise SymbenchError(f"{path}: listed in {IMPORT_JSON} but does not exist")
        arrays = _read_file(path, robot.n_legs, robot.name)
        n = check_trajectory(arrays, robot.n_legs, period, str(path))
        scenario = {k: None for k in SCENARIO_KEYS} | entry.get("scenario", {})
        loaded.append((arrays, n, {"robot": robot.name, **scenario}, entry["file"]))
    records = []
    for i, (arrays, n, scenario, source) in enumerate(loaded):
        file = f"trajectories/{i:05d}.parquet"
        sha = write_trajectory(root / file, arrays, robot.n_legs)
        records.append({"id": i, "file": file, "sha256": sha, "n_steps": n,
                        "scenario": scenario, "source_file": source})
    write_metadata(root, {
        "id": dataset_id, "source": "imported", "imported_from": str(folder),
        "robot": robot.name, "n_legs": robot.n_legs, "robot_spec_hash": robot.spec_hash(),
        "raw_schema_version": SCHEMA_VERSION, "record_period_s": period,
        "versions": library_versions(), "trajectories": records, "failures": [],
        "n_samples": sum(n - 1 for _, n, _, _ in loaded),
        "repair_command": f"symbench data import {folder} --id {dataset_id} --force",
    })
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
            np.savez(buf, **arrays)
            write_bytes_atomic(folder / name, buf.getvalue())
        scenario = {k: v for k, v in rec["scenario"].items() if k in SCENARIO_KEYS and v is not None}
        entries.append({"file": name, "scenario": scenario})
    atomic_write_json(folder / IMPORT_JSON, {
        "robot": dataset.robot, "record_period_s": dataset.metadata["record_period_s"],
        "trajectories": entries})
    return folder

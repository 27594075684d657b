"""`import.json`, validated: the robot, the log's sampling period, the frame of its base
vectors, the columns it does not have reliably, the trajectory files with their scenarios, and
provenance. Each field of the right type and finite; scenario values checked with the value
named (a direction from the known set, an inclination within 0..180, a heading that is a
number); no file twice (it would land in the training and the test split at once), every file
inside the folder. Top-level keys that are not fields (`source`, `license`, `notes`, ...) are
kept as provenance when their value is text, a number or a flag; a key close to a field's name
(a misspelt `trajectories` would otherwise import every file of the folder) is refused."""

from __future__ import annotations

import difflib
from pathlib import Path
from typing import Annotated, Any, Literal

from pydantic import BaseModel, ConfigDict, Field, ValidationError

from symbench.core.common.errors import SymbenchError
from symbench.core.common.jsonfile import read_json
from symbench.core.data.importing.derive import UNKNOWABLE
from symbench.core.data.storage.scenario_fields import ScenarioFields

IMPORT_JSON = "import.json"
SUFFIXES = (".parquet", ".npz")
Provenance = str | int | float | bool


class TrajectoryFile(BaseModel):
    model_config = ConfigDict(extra="forbid", strict=True, frozen=True)

    file: Annotated[str, Field(min_length=1)]
    scenario: ScenarioFields = ScenarioFields()


class ImportManifest(BaseModel):
    model_config = ConfigDict(extra="forbid", strict=True, frozen=True)

    robot: Annotated[str, Field(min_length=1)]
    record_period_s: Annotated[float, Field(gt=0, allow_inf_nan=False)]
    base_frame: Literal["world", "body"] = "world"
    unknown: list[Literal[UNKNOWABLE]] = []  # type: ignore[valid-type]
    trajectories: list[TrajectoryFile] | None = None
    provenance: dict[str, Provenance] = {}


FIELDS = tuple(ImportManifest.model_fields)


def _explain(error: ValidationError, path: Path, data: Any) -> SymbenchError:
    """One line: each problem with its field, the trajectory's file and the value given."""
    problems = []
    for e in error.errors():
        loc = list(e["loc"])
        where = ".".join(str(p) for p in loc) or "(top level)"
        if len(loc) > 1 and loc[0] == "trajectories" and isinstance(loc[1], int):
            try:
                where += f" (file {data['trajectories'][loc[1]]['file']})"
            except (KeyError, IndexError, TypeError):
                pass
        given = f", got {e['input']!r}" if loc and e["type"] != "missing" else ""
        if isinstance(e.get("input"), (dict, list)):
            given = ""
        problems.append(f"{where}: {e['msg']}{given}")
    return SymbenchError(f"{path}: " + "; ".join(problems))


def _split_provenance(data: Any, path: Path) -> Any:
    """Top-level keys that are not fields moved into `provenance` (text, numbers, flags)."""
    if not isinstance(data, dict):
        return data
    data = dict(data)
    given = data.get("provenance", {})
    provenance = dict(given) if isinstance(given, dict) else given  # not a dict: refused below
    for key in [k for k in data if k not in FIELDS]:
        close = difflib.get_close_matches(key, FIELDS, n=1, cutoff=0.75)
        if close:
            raise SymbenchError(f"{path}: unknown field '{key}' (did you mean '{close[0]}'?)")
        value = data.pop(key)
        if not isinstance(value, (str, int, float, bool)):
            raise SymbenchError(
                f"{path}: '{key}' is not a field of {IMPORT_JSON}; other keys are kept as "
                f"provenance but must hold text, a number or true/false, got {type(value).__name__}"
            )
        if isinstance(provenance, dict):
            provenance[key] = value
    if provenance:
        data["provenance"] = provenance
    return data


def read_manifest(folder: Path) -> tuple[ImportManifest, list[TrajectoryFile]]:
    """The manifest of `folder` and its trajectory files (every *.parquet and *.npz of the
    folder, in name order, when it lists none)."""
    path = folder / IMPORT_JSON
    if not path.is_file():
        raise SymbenchError(
            f"{folder} has no {IMPORT_JSON} naming the robot and the record "
            "period (see docs/data-format.md, 'Importing a real robot's logs')"
        )
    data = _split_provenance(read_json(path, "import"), path)
    try:
        manifest = ImportManifest.model_validate(data)
    except ValidationError as exc:
        raise _explain(exc, path, data) from None
    entries = manifest.trajectories
    if entries is None:
        entries = [
            TrajectoryFile(file=p.name) for p in sorted(folder.iterdir()) if p.suffix in SUFFIXES
        ]
    if not entries:
        raise SymbenchError(f"{folder}: no *.parquet or *.npz trajectory files")
    seen: dict[Path, str] = {}
    for entry in entries:
        resolved = (folder / entry.file).resolve()
        if Path(entry.file).suffix not in SUFFIXES:
            raise SymbenchError(f"{path}: {entry.file} is neither .parquet nor .npz")
        if not resolved.is_relative_to(folder.resolve()):
            raise SymbenchError(f"{path}: {entry.file} is not inside {folder}")
        if resolved in seen:
            raise SymbenchError(
                f"{path}: {entry.file} is listed twice (also as {seen[resolved]}); "
                "a trajectory imported twice can land in training and test at once"
            )
        seen[resolved] = entry.file
    return manifest, entries

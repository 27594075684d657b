"""`import.json`, validated: the robot, the record period and the trajectory files with their
scenarios, each field of the right type and finite, no unknown field (a misspelt
`trajectories` would otherwise import every file of the folder), no file twice (it would land
in the training and the test split at once), every file inside the folder."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

from pydantic import BaseModel, ConfigDict, Field, ValidationError

from symbench.core.common.errors import SymbenchError
from symbench.core.common.jsonfile import read_json
from symbench.core.common.validation import explain
from symbench.core.data.scenario_fields import ScenarioFields

IMPORT_JSON = "import.json"
SUFFIXES = (".parquet", ".npz")


class TrajectoryFile(BaseModel):
    model_config = ConfigDict(extra="forbid", strict=True, frozen=True)

    file: Annotated[str, Field(min_length=1)]
    scenario: ScenarioFields = ScenarioFields()


class ImportManifest(BaseModel):
    model_config = ConfigDict(extra="forbid", strict=True, frozen=True)

    robot: Annotated[str, Field(min_length=1)]
    record_period_s: Annotated[float, Field(gt=0, allow_inf_nan=False)]
    trajectories: list[TrajectoryFile] | None = None


def read_manifest(folder: Path) -> tuple[ImportManifest, list[TrajectoryFile]]:
    """The manifest of `folder` and its trajectory files (every *.parquet and *.npz of the
    folder, in name order, when it lists none)."""
    path = folder / IMPORT_JSON
    if not path.is_file():
        raise SymbenchError(
            f"{folder} has no {IMPORT_JSON} naming the robot and the record "
            "period (see docs/data-format.md, 'Importing a real robot's logs')"
        )
    try:
        manifest = ImportManifest.model_validate(read_json(path, "import"))
    except ValidationError as exc:
        raise explain(exc, str(path)) from None
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

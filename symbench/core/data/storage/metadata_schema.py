"""What a dataset's metadata.json must hold, checked when it is read: the content hash proves
the file unchanged since it was last hashed, not that it was written by symbench, so a
re-hashed file with a missing key, a wrong type or a sample count that disagrees with its own
trajectories is refused here with the field named, instead of failing somewhere later."""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import BaseModel, ConfigDict, Field, model_validator

from symbench.core.data.storage.scenario_fields import StoredScenario

Sha256 = Annotated[str, Field(pattern=r"^[0-9a-f]{64}$")]
# inside the dataset folder: no '..', no absolute path
TrajectoryFile = Annotated[
    str, Field(pattern=r"^trajectories/[A-Za-z0-9][A-Za-z0-9_.-]*\.parquet$")
]


class _Strict(BaseModel):
    model_config = ConfigDict(strict=True, frozen=True)


class StoredTrajectory(_Strict):
    model_config = ConfigDict(extra="forbid")

    id: Annotated[int, Field(ge=0)]
    file: TrajectoryFile
    sha256: Sha256
    n_steps: Annotated[int, Field(ge=2)]
    scenario: StoredScenario
    source_file: str | None = None  # imported datasets: the file it came from


class Failure(_Strict):
    model_config = ConfigDict(extra="forbid")

    id: Annotated[int, Field(ge=0)]
    scenario: StoredScenario
    failure: str


class DatasetMetadata(_Strict):
    """The fields every dataset has; generated and imported ones add a few of their own."""

    model_config = ConfigDict(extra="allow")

    format: Literal["symbench-dataset"]
    format_version: Literal[1]
    id: str
    source: Literal["generated", "imported"]
    robot: str
    n_legs: Annotated[int, Field(ge=1)]
    robot_spec_hash: str
    raw_schema_version: int
    record_period_s: Annotated[float, Field(gt=0, allow_inf_nan=False)]
    versions: dict[str, str]
    trajectories: list[StoredTrajectory]
    failures: list[Failure]
    n_samples: Annotated[int, Field(ge=0)]
    repair_command: str
    content_hash: Sha256

    @model_validator(mode="after")
    def _consistent(self) -> DatasetMetadata:
        ids = [t.id for t in self.trajectories] + [f.id for f in self.failures]
        if len(set(ids)) != len(ids):
            raise ValueError("a trajectory id appears twice")
        if len({t.file for t in self.trajectories}) != len(self.trajectories):
            raise ValueError("a trajectory file appears twice")
        samples = sum(t.n_steps - 1 for t in self.trajectories)
        if self.n_samples != samples:
            raise ValueError(f"n_samples is {self.n_samples}, its trajectories hold {samples}")
        return self

"""Result records: everything needed to trust and reproduce one run, validated both ways.

A record is JSON, validated by a versioned pydantic schema when written and when read, so a
record with a missing field, a foreign schema version or a dataset hash that does not match
the dataset it names is refused with a message saying which.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any, Literal

from pydantic import BaseModel, ConfigDict, Field, ValidationError

from symbench.core.atomic import write_text_atomic
from symbench.core.errors import SymbenchError

RECORD_SCHEMA_VERSION = 1


class _Strict(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)


class ModelInfo(_Strict):
    name: str
    backend: Literal["torch", "jax"]
    view: str
    variant: str
    equivariant: bool = Field(description="whether the model claims the robot's symmetry")
    hyperparameters: dict[str, Any]
    learning_rate: float
    parameters: int = Field(ge=0, description="number of trainable parameters")


class DatasetInfo(_Strict):
    id: str
    content_hash: str = Field(min_length=64, max_length=64, description="SHA-256, hex")
    robot_spec_hash: str
    preset: str


class SampleCounts(_Strict):
    train: int = Field(ge=0)
    val: int = Field(ge=0)
    test: int = Field(ge=0)
    train_trajectories: int = Field(ge=0)
    val_trajectories: int = Field(ge=0)
    test_trajectories: int = Field(ge=0)


class TrainingInfo(_Strict):
    epochs: int = Field(ge=0)
    best_epoch: int = Field(ge=0)
    stopped_early: bool
    best_val_loss: float
    batch_size: int


class ResultRecord(_Strict):
    schema_version: Literal[1] = RECORD_SCHEMA_VERSION
    created: str = Field(description="UTC time, ISO 8601")
    model: ModelInfo
    robot: str
    dataset: DatasetInfo
    split: str
    seed: int
    samples: SampleCounts
    training: TrainingInfo
    metrics: dict[str, dict[str, Any]] = Field(description="evaluator name -> its metrics")
    timings_s: dict[str, float]
    hardware: dict[str, Any]
    versions: dict[str, str]
    git_commit: str

    def key(self) -> str:
        """What identifies a run in a sweep: one record per key."""
        m = self.model
        return f"{self.robot}__{self.split}__{m.name}__{m.variant}__{m.backend}__seed{self.seed}"


def _explain(error: ValidationError, source: str) -> SymbenchError:
    problems = []
    for e in error.errors():
        where = ".".join(str(p) for p in e["loc"]) or "(record)"
        problems.append(f"{where}: {e['msg']}")
    return SymbenchError(f"invalid result record {source}: " + "; ".join(problems))


def write_record(record: ResultRecord | dict, path: Path) -> ResultRecord:
    """Validate, then write atomically; returns the validated record."""
    try:
        record = ResultRecord.model_validate(record if isinstance(record, dict) else record.model_dump())
    except ValidationError as exc:
        raise _explain(exc, str(path)) from None
    write_text_atomic(path, record.model_dump_json(indent=2) + "\n")
    return record


def read_record(path: Path) -> ResultRecord:
    """Read and validate a record; a foreign or broken file is a clear error."""
    try:
        data = json.loads(Path(path).read_text())
    except (OSError, json.JSONDecodeError) as exc:
        raise SymbenchError(f"cannot read result record {path}: {exc}") from None
    version = data.get("schema_version") if isinstance(data, dict) else None
    if version != RECORD_SCHEMA_VERSION:
        raise SymbenchError(f"result record {path} has schema version {version!r}; "
                            f"this symbench reads version {RECORD_SCHEMA_VERSION}")
    try:
        return ResultRecord.model_validate(data)
    except ValidationError as exc:
        raise _explain(exc, str(path)) from None


def check_dataset_hash(record: ResultRecord, content_hash: str, source: str = "") -> None:
    """Refuse a record made on a different version of the dataset it names."""
    if record.dataset.content_hash != content_hash:
        raise SymbenchError(
            f"result record {source or record.key()} was made on dataset {record.dataset.id} "
            f"with content hash {record.dataset.content_hash[:12]}..., but that dataset now has "
            f"hash {content_hash[:12]}...: regenerate the record or the dataset")


def json_schema() -> dict[str, Any]:
    """The record's JSON Schema (documented in the README)."""
    return ResultRecord.model_json_schema()

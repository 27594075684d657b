"""Result records: everything needed to trust and reproduce one run, validated and sealed.

A record is JSON, validated by a versioned pydantic schema when written and when read, so a
record with a missing field or a foreign schema version is refused with a message saying
which. Since schema 2 a record is
sealed: `seal` is the SHA-256 of its canonical JSON without the seal, so a value edited by
hand is detected whenever the record is read. The seal is not a signature (anyone can re-seal
an edited record); `symbench verify` re-runs a record to check its numbers.

A run's identity is its configuration: the data (dataset id and content hash), the preset
(budgets), split, seed, model, input variant, backend, evaluators and training configuration.
The key (`run_key`), which names the record file, holds what tells runs apart at a glance
(dataset id, preset, split, model, variant, backend, protocol, a matched size, the build
keywords set by `--size`, seed);
`RecordBody.configuration` holds all of it, so a sweep can tell a finished run from another
run's record at the same path.

Names that end up in file names (robot, split, model, variant, dataset, preset) must be safe
identifiers (a preset may end in `@vN`, an earlier dataset version's key), so no record can
make publish or leaderboard write outside their folder.
Schema-1 records (unsealed, without provenance) are read for display only
(`read_display_record`); everything that trusts a record uses `read_record`.
"""

from __future__ import annotations

import hashlib
import json
from collections.abc import Mapping
from pathlib import Path
from typing import Annotated, Any, Final, Literal

from pydantic import BaseModel, ConfigDict, Field, StringConstraints, ValidationError

from symbench.core.common.atomic import write_text_atomic
from symbench.core.common.errors import SymbenchError
from symbench.core.common.identifiers import IDENTIFIER, IDENTIFIER_LENGTH, PRESET_KEY
from symbench.core.common.jsonfile import parse_json
from symbench.core.common.validation import explain
from symbench.core.config.protocols import Protocol, StoppedBy

RECORD_SCHEMA_VERSION: Final = 2
LEGACY_SCHEMA_VERSION = 1  # unsealed, no provenance: shown by `symbench leaderboard` only

Identifier = Annotated[str, StringConstraints(pattern=IDENTIFIER, max_length=IDENTIFIER_LENGTH)]
PresetKey = Annotated[str, StringConstraints(pattern=PRESET_KEY, max_length=IDENTIFIER_LENGTH)]
Sha256 = Annotated[str, StringConstraints(pattern=r"^[0-9a-f]{64}$")]


def run_key(
    dataset: str,
    preset: str,
    split: str,
    model: str,
    variant: str,
    backend: str,
    protocol: str,
    seed: int,
    parameters: int | None = None,
    sizes: Mapping[str, int] | None = None,
) -> str:
    """What identifies a run by name: one record per key, written as `<key>.json`, e.g.
    `hexa-climb-small-v5__small__iid__sdnn__acc__torch__converge__seed0`. The dataset id names
    the data (a standard id names its robot and grid), the preset the budgets, the protocol
    how training stops, `__p<N>` a size matched to N parameters (`--parameters`), `__<name>-<v>`
    each build keyword set by `--size name=v`, by name (default sizes add nothing, so their
    keys stay as they were); all are in the key, so runs on other data, budgets, protocols or
    sizes never share a record file or a checkpoint folder."""
    size = "" if parameters is None else f"__p{parameters}"
    size += "".join(f"__{name}-{value}" for name, value in sorted((sizes or {}).items()))
    return (
        f"{dataset}__{preset}__{split}__{model}__{variant}__{backend}__{protocol}{size}__seed{seed}"
    )


class _Strict(BaseModel):
    # no NaN or infinity in a float field: JSON has none, and pydantic would write them as
    # null, a record that no longer reads back
    model_config = ConfigDict(extra="forbid", frozen=True, allow_inf_nan=False)


class PluginInfo(_Strict):
    """Which code built the network: enough to install the same plugin and see if it changed."""

    module: str = Field(description="the module holding the model's build function")
    distribution: str = Field(description="the installed distribution providing that module")
    version: str
    source_sha256: Sha256 = Field(description="SHA-256 over the plugin package's *.py files")


class RobotPlugin(_Strict):
    """Which plugin registered the robot, so that the same spec can be installed again (its
    content is the dataset's `robot_spec_hash`): a built-in robot's is symbench's."""

    plugin: str = Field(description="the entry point (or in-process name) of the plugin")
    distribution: str = Field(description="the installed distribution shipping that plugin")
    version: str


class ModelInfoV1(_Strict):
    name: Identifier
    backend: Literal["torch", "jax"]
    view: Identifier
    variant: Identifier
    equivariant: bool = Field(description="whether the model claims the robot's symmetry")
    hyperparameters: dict[str, Any]
    learning_rate: float
    parameters: int = Field(ge=0, description="number of trainable parameters")


class ModelInfo(ModelInfoV1):
    hyperparameters: dict[str, Any] = Field(
        description="every keyword of the build function, defaults included"
    )
    plugin: PluginInfo
    version: int = Field(
        default=1,
        ge=1,
        description="the model entry's version: what the network computes (records made "
        "before versions were recorded read as version 1)",
    )
    matched_parameters: int | None = Field(
        default=None,
        ge=1,
        # left out of the JSON when None: a default-size record is written (and sealed) as
        # before this field existed
        exclude_if=lambda value: value is None,
        description="the parameter count the widths were scaled to (`--parameters`); absent: "
        "the model's default size",
    )
    sizes: dict[Identifier, int] | None = Field(
        default=None,
        # left out when None, as matched_parameters: records made before the field, whose
        # `--size` keywords only training.config.hyper names, keep their seals and keys
        exclude_if=lambda value: value is None,
        description="the build keywords set by name (`--size`), part of the run key; absent: "
        "none set (or a record made before the field)",
    )


class DatasetInfo(_Strict):
    id: Identifier
    content_hash: Sha256
    robot_spec_hash: str
    preset: PresetKey


class SampleCounts(_Strict):
    train: int = Field(ge=0)
    val: int = Field(ge=0)
    test: int = Field(ge=0)
    train_trajectories: int = Field(ge=0)
    val_trajectories: int = Field(ge=0)
    test_trajectories: int = Field(ge=0)


class TrainingInfoV1(_Strict):
    epochs: int = Field(ge=0)
    best_epoch: int = Field(ge=0)
    stopped_early: bool
    best_val_loss: float
    batch_size: int


class TrainingConfig(_Strict):
    """The `TrainConfig` a run used, defaults resolved (everything but the progress bar).
    Records from before the `converge` protocol hold no protocol: they were trained under
    the paper's rule, and read so."""

    seed: int
    batch_size: int = Field(ge=1)
    protocol: Protocol = "paper"
    max_steps: int | None = Field(default=None, ge=1)
    eval_every: int | None = Field(default=None, ge=1)
    patience: int | None = Field(default=None, ge=1)
    val_stride: int = Field(default=1, ge=1, description="validation rows: every n-th")
    max_epochs: int = Field(ge=1)
    stop_ratio: float
    stop_patience: int = Field(ge=1)
    learning_rate: float = Field(gt=0)
    hyper: dict[str, Any] = Field(description="overrides of the build function's defaults")
    compile: bool


class TrainingInfo(TrainingInfoV1):
    """`epochs`: full passes over the training data; `best_epoch`: the validation check of
    the kept parameters (an epoch under `paper`); `steps`: gradient steps; `stopped_by`:
    patience or budget (converge, cosine), overfitting-rule or epoch-cap (paper). Records from
    before these fields leave them out."""

    stopped_by: StoppedBy | None = None
    stop_reason: str | None = None
    steps: int | None = Field(default=None, ge=0)
    best_step: int | None = Field(default=None, ge=0)
    config: TrainingConfig
    checkpoint_sha256: dict[str, Sha256] = Field(
        min_length=1, description="file name -> SHA-256 of the best checkpoint's files"
    )


class RecordV1(_Strict):
    """Schema 1: still readable for display, never trusted."""

    schema_version: Literal[1]
    created: str = Field(description="UTC time, ISO 8601")
    model: ModelInfoV1
    robot: Identifier
    dataset: DatasetInfo
    split: Identifier
    seed: int
    samples: SampleCounts
    training: TrainingInfoV1
    metrics: dict[str, dict[str, Any]] = Field(description="evaluator name -> its metrics")
    timings_s: dict[str, float]
    hardware: dict[str, Any]
    versions: dict[str, str]
    git_commit: str

    def key(self, split: str | None = None, variant: str | None = None) -> str:
        """The run's key (`run_key`), safe as a file name: one record per key. With `split`
        (and `variant`): the key of the run that trains on them as its own (`RunSpec.key`)."""
        m, d = self.model, self.dataset
        return run_key(
            d.id,
            d.preset,
            split or self.split,
            m.name,
            variant or m.variant,
            m.backend,
            self.protocol(),
            self.seed,
            getattr(m, "matched_parameters", None),
            getattr(m, "sizes", None),
        )

    def protocol(self) -> Protocol:
        """Schema 1 predates the `converge` protocol: its runs were trained under the paper's."""
        return "paper"


class RecordBody(RecordV1):
    """A schema-2 record before it is sealed: what the runner fills in."""

    schema_version: Literal[2] = RECORD_SCHEMA_VERSION  # type: ignore[assignment]  # narrows v1
    model: ModelInfo
    training: TrainingInfo
    robot_plugin: RobotPlugin | None = Field(
        default=None, description="records from before it was recorded leave it out"
    )

    def protocol(self) -> Protocol:
        return self.training.config.protocol

    def configuration(self) -> dict[str, Any]:
        """Everything the run was asked to do, as JSON values by a readable name: two records
        of one configuration differ only in what the run measured and where it ran. Compared
        with `run_config.configuration` of a requested run (same names)."""
        m, config = self.model, self.training.config.model_dump(mode="json")
        matched = (
            {} if m.matched_parameters is None else {"matched parameters": m.matched_parameters}
        )
        return {
            **matched,
            "dataset": self.dataset.id,
            "dataset content hash": self.dataset.content_hash,
            "preset": self.dataset.preset,
            "robot": self.robot,
            "split": self.split,
            "seed": self.seed,
            "model": m.name,
            "model version": m.version,
            "backend": m.backend,
            "input variant": m.variant,
            "evaluators": sorted(self.metrics),
            "hyper-parameters": json.loads(json.dumps(m.hyperparameters)),
            **{f"training {name}": value for name, value in config.items()},
        }


class ResultRecord(RecordBody):
    seal: Sha256 = Field(description="SHA-256 of the canonical JSON of every other field")


def seal_of(data: dict[str, Any]) -> str:
    """The SHA-256 of the record's JSON data without its seal, keys sorted."""
    body = {k: v for k, v in data.items() if k != "seal"}
    text = json.dumps(body, sort_keys=True, separators=(",", ":"), ensure_ascii=True)
    return hashlib.sha256(text.encode()).hexdigest()


def _explain(error: ValidationError, source: str) -> SymbenchError:
    return explain(error, f"invalid result record {source}")


def write_record(record: RecordBody | dict, path: Path) -> ResultRecord:
    """Validate, seal (a seal already present is recomputed), write atomically; returns the
    sealed record."""
    data = record.model_dump(mode="json") if isinstance(record, BaseModel) else dict(record)
    data.pop("seal", None)
    try:
        body = RecordBody.model_validate(data)
    except ValidationError as exc:
        raise _explain(exc, str(path)) from None
    data = json.loads(body.model_dump_json())  # exactly what a reader will parse
    data["seal"] = seal_of(data)
    write_text_atomic(Path(path), json.dumps(data, indent=2) + "\n")
    return ResultRecord.model_validate(data)


def _load(path: Path) -> dict[str, Any]:
    try:
        text = Path(path).read_bytes()
    except OSError as exc:
        raise SymbenchError(f"cannot read result record {path}: {exc.strerror or exc}") from None
    data = parse_json(text, f"cannot read result record {path}")
    if not isinstance(data, dict):
        raise SymbenchError(f"result record {path} is not a JSON object")
    return data


def _sealed(data: dict[str, Any], path: Path) -> ResultRecord:
    if data.get("schema_version") == LEGACY_SCHEMA_VERSION:
        raise SymbenchError(
            f"{path}: record is not sealed (schema {LEGACY_SCHEMA_VERSION}); re-run it"
        )
    if data.get("schema_version") != RECORD_SCHEMA_VERSION:
        raise SymbenchError(
            f"result record {path} has schema version "
            f"{data.get('schema_version')!r}; this symbench reads version "
            f"{RECORD_SCHEMA_VERSION}"
        )
    if data.get("seal") != seal_of(data):
        raise SymbenchError(f"{path}: record does not match its seal (edited after it was written)")
    try:
        return ResultRecord.model_validate(data)
    except ValidationError as exc:
        raise _explain(exc, str(path)) from None


def read_record(path: Path) -> ResultRecord:
    """A sealed record whose content matches its seal; anything else is a clear error."""
    return _sealed(_load(path), path)


def read_display_record(path: Path) -> RecordV1:
    """A sealed record, or a schema-1 one (validated, unsealed) for tables of old boards."""
    data = _load(path)
    if data.get("schema_version") != LEGACY_SCHEMA_VERSION:
        return _sealed(data, path)
    try:
        return RecordV1.model_validate(data)
    except ValidationError as exc:
        raise _explain(exc, str(path)) from None

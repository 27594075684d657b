"""Everything one record says about where its numbers come from, as labelled values for the
entry pages, with its verification status: whether its seal matches (`read_record`) and
whether the published board holds it, in full and in a word for the seeds' summary. Its
metrics as `metrics.evaluator_metrics` shows them. Schema-1 records lack fields: those read
"not recorded"."""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path
from typing import Any, NamedTuple

from symbench.core.board.leaderboard import RECORDS, protocol_of
from symbench.core.board.site.metrics import EvaluatorMetrics, evaluator_metrics
from symbench.core.board.site.reproduce import run_command, verify_command
from symbench.core.common.errors import SymbenchError
from symbench.core.runs.results import RecordV1, read_display_record, read_record

NOT_RECORDED = "not recorded (schema 1)"
Fields = tuple[tuple[str, str], ...]  # (label, value) in the order shown


class Status(NamedTuple):
    ok: bool
    text: str


@dataclass(frozen=True)
class Provenance:
    seed: int
    record: str  # the record file, as the command was given it
    seal: str  # "sealed, seal matches" or what is wrong
    board: str  # whether the published board holds this record
    verdict: str  # both in a few words: "sealed, on the board"
    sections: tuple[tuple[str, Fields], ...]  # (title, fields)
    metrics: tuple[EvaluatorMetrics, ...]
    reproduce: str
    verify: str


def provenance(path: Path, record: RecordV1, board: Path) -> Provenance:
    seal, published = seal_status(path), board_status(record, board)
    return Provenance(
        seed=record.seed,
        record=str(path),
        seal=seal.text,
        board=published.text,
        verdict=verdict(seal.ok, published.ok),
        sections=(
            ("Record", _record(record)),
            ("Model", _model(record)),
            ("Plugin", _plugin(record)),
            ("Dataset", _dataset(record)),
            ("Training", _training(record)),
            ("Training configuration", _config(record)),
            ("Checkpoint", _checkpoint(record)),
            ("Timings (s)", _mapping(record.timings_s)),
            ("Hardware", _mapping(record.hardware)),
            ("Versions", _mapping(record.versions)),
        ),
        metrics=evaluator_metrics(record.metrics),
        reproduce=run_command(record),
        verify=verify_command(path),
    )


def seal_status(path: Path) -> Status:
    """Read as `symbench publish` and `symbench verify` read it: sealed and unchanged."""
    try:
        read_record(path)
    except SymbenchError as exc:
        return Status(False, f"not verified: {exc}")
    return Status(True, "sealed, seal matches")


def board_status(record: RecordV1, board: Path) -> Status:
    """Whether the board's record under this run's key is this very record."""
    published = board / RECORDS / f"{record.key()}.json"
    if not published.is_file():
        return Status(False, f"not on the published board (no {published})")
    try:
        same = read_display_record(published) == record
    except SymbenchError as exc:
        return Status(
            False, f"not on the published board: its record for this run is unreadable ({exc})"
        )
    if same:
        return Status(True, f"on the published board ({published})")
    return Status(
        False, f"not on the published board: {published} is a different record of this run"
    )


def verdict(sealed: bool, published: bool) -> str:
    if not sealed:
        return "not verified"
    return "sealed, on the board" if published else "sealed, not on the board"


def text(value: Any) -> str:
    """A value as shown: text as it is, anything else as JSON (keys sorted)."""
    return value if isinstance(value, str) else json.dumps(value, sort_keys=True)


def _mapping(values: dict[str, Any]) -> Fields:
    return tuple((name, text(values[name])) for name in sorted(values))


def _record(r: RecordV1) -> Fields:
    return (
        ("run key", r.key()),
        ("schema version", str(r.schema_version)),
        ("seal", str(getattr(r, "seal", NOT_RECORDED))),
        ("created", r.created),
        ("git commit", r.git_commit),
        ("robot", r.robot),
        ("split", r.split),
        ("seed", str(r.seed)),
        ("protocol", protocol_of(r)),
    )


def _model(r: RecordV1) -> Fields:
    m = r.model
    return (
        ("name", m.name),
        ("backend", m.backend),
        ("view", m.view),
        ("variant", m.variant),
        ("equivariant", text(m.equivariant)),
        ("parameters", str(m.parameters)),
        ("learning rate", text(m.learning_rate)),
        ("hyper-parameters", text(m.hyperparameters)),
    )


def _plugin(r: RecordV1) -> Fields:
    plugin = getattr(r.model, "plugin", None)
    if plugin is None:
        return (("plugin", NOT_RECORDED),)
    return (
        ("distribution", plugin.distribution),
        ("module", plugin.module),
        ("version", plugin.version),
        ("source SHA-256", plugin.source_sha256),
    )


def _dataset(r: RecordV1) -> Fields:
    d, s = r.dataset, r.samples
    return (
        ("id", d.id),
        ("preset", d.preset),
        ("content hash", d.content_hash),
        ("robot spec hash", d.robot_spec_hash),
        ("samples (train / val / test)", f"{s.train} / {s.val} / {s.test}"),
        (
            "trajectories (train / val / test)",
            f"{s.train_trajectories} / {s.val_trajectories} / {s.test_trajectories}",
        ),
    )


def _training(r: RecordV1) -> Fields:
    t = r.training

    def recorded(name: str) -> str:
        value = getattr(t, name, None)
        return NOT_RECORDED if value is None else text(value)

    return (
        ("epochs", str(t.epochs)),
        ("best epoch", str(t.best_epoch)),
        ("steps", recorded("steps")),
        ("best step", recorded("best_step")),
        ("stopped by", recorded("stopped_by")),
        ("stop reason", recorded("stop_reason")),
        ("stopped early", text(t.stopped_early)),
        ("best validation loss", text(t.best_val_loss)),
        ("batch size", str(t.batch_size)),
    )


def _config(r: RecordV1) -> Fields:
    config = getattr(r.training, "config", None)
    if config is None:
        return (("configuration", NOT_RECORDED),)
    return _mapping(config.model_dump(mode="json"))


def _checkpoint(r: RecordV1) -> Fields:
    hashes = getattr(r.training, "checkpoint_sha256", None)
    if hashes is None:
        return (("checkpoint", NOT_RECORDED),)
    return tuple((f"{name} SHA-256", hashes[name]) for name in sorted(hashes))

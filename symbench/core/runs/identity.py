"""What is at a run's record path, and whether the run may replace it: a record of another
configuration is never replaced unless the run says so (`RunSpec.overwrite`)."""

from __future__ import annotations

import json
from typing import Any, Literal

from symbench.core.common.errors import SymbenchError
from symbench.core.runs.results import read_record
from symbench.core.runs.run_config import configuration
from symbench.core.runs.spec import RunSpec

RecordState = Literal["missing", "unreadable", "same", "different"]


def _shown(name: str, value: Any) -> str:
    if name == "dataset content hash" and isinstance(value, str):
        return f"{value[:12]}..."
    if name == "evaluators" and isinstance(value, list):
        return ",".join(map(str, value)) or "none"
    return json.dumps(value) if not isinstance(value, str) else value


def difference(found: dict[str, Any], wanted: dict[str, Any]) -> str | None:
    """The first configuration entry in which a found record differs from a wanted run, as
    "preset smoke in the record, small in this run"; None when they agree on every wanted
    entry."""
    for name, value in wanted.items():
        if found.get(name) != value:
            was = _shown(name, found.get(name))
            return f"{name} {was} in the record, {_shown(name, value)} in this run"
    return None


def record_state(spec: RunSpec, content_hash: str | None = None) -> tuple[RecordState, str]:
    """What is at the run's record path: nothing, a record that cannot be trusted (corrupt,
    edited, schema 1: rewritten), a record of this very configuration, or one of another
    configuration; with the reason when untrusted or of another configuration."""
    path = spec.record_path
    if not path.is_file():
        return "missing", ""
    try:
        record = read_record(path)
    except SymbenchError as exc:
        return "unreadable", str(exc)
    why = difference(record.configuration(), configuration(spec, content_hash))
    return ("same", "") if why is None else ("different", why)


def refusal(spec: RunSpec, why: str, more: int = 0) -> SymbenchError:
    """The error for a record of another configuration at the run's path (`more`: how many
    other records of the command differ too)."""
    others = f" (and {more} more record{'s' if more > 1 else ''})" if more else ""
    it = "them" if more else "it"
    return SymbenchError(
        f"{spec.record_path} is a record of another configuration ({why}){others}; pass "
        f"--overwrite to run {it} again and replace {it}, or choose another --output"
    )


def check_replaceable(spec: RunSpec, content_hash: str | None = None) -> None:
    """Refuses a run whose record path holds a record of another configuration, unless the
    run says `overwrite`."""
    state, why = record_state(spec, content_hash)
    if state == "different" and not spec.overwrite:
        raise refusal(spec, why)

"""The summary at the top of an entry page: a row per seed with its headline numbers and
verification status, so that the seeds are compared at a glance, then their mean with its
95 % bootstrap interval over seeds (`statistics.mean_interval`, as the board's cells)."""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any, NamedTuple

import numpy as np

from symbench.core.board.cells import count, metric_parts, number
from symbench.core.board.site.provenance import NOT_RECORDED, Provenance
from symbench.core.board.statistics import mean_interval
from symbench.core.runs.results import RecordV1

MISSING = "-"  # as the board writes a missing value


@dataclass(frozen=True)
class Column:
    header: str
    title: str  # what it holds, the header's tooltip
    numeric: bool  # averaged over seeds in the last row


@dataclass(frozen=True)
class SeedRow:
    seed: int
    cells: tuple[str, ...]  # one per column


class Mean(NamedTuple):
    mean: str  # "0.329"; "" for a text column
    interval: str  # "[0.301, 0.351]"; "" below two seeds with a value


@dataclass(frozen=True)
class SeedSummary:
    columns: tuple[Column, ...]
    rows: tuple[SeedRow, ...]
    mean: tuple[Mean, ...]  # one per column
    over: str  # "3 seeds"


@dataclass(frozen=True)
class _Numeric:
    column: Column
    read: Callable[[RecordV1], Any]  # the value, None when the record has none


def _metric(evaluator: str, name: str) -> Callable[[RecordV1], Any]:
    return lambda record: record.metrics.get(evaluator, {}).get(name)


def _numeric(header: str, title: str, read: Callable[[RecordV1], Any]) -> _Numeric:
    return _Numeric(Column(header, title, True), read)


NUMERIC = (
    _numeric("test RMSE (N·m)", "torque-error · rmse", _metric("torque-error", "rmse")),
    _numeric(
        "closed-loop score",
        "closed-loop · pd_normalized_score: time held between floor (0) and oracle (1)",
        _metric("closed-loop", "pd_normalized_score"),
    ),
    _numeric(
        "tracking score",
        "closed-loop · pd_tracking_score: tracking cost between floor (0) and oracle (1)",
        _metric("closed-loop", "pd_tracking_score"),
    ),
    _numeric("steps", "gradient steps trained", lambda r: getattr(r.training, "steps", None)),
    _numeric(
        "wall time training (s)",
        "timings_s · training_s: what this run spent training; a run resumed from its "
        "checkpoints times only the rest",
        lambda r: r.timings_s.get("training_s"),
    ),
)
TEXT = (
    Column("stop reason", "why training stopped", False),
    Column("verification", "seal, and whether the published board holds the record", False),
)


def seed_summary(runs: Sequence[tuple[RecordV1, Provenance]]) -> SeedSummary:
    """The summary of one board row's seeds; a numeric column only where a seed has it."""
    numeric = [c for c in NUMERIC if any(_value(c, r) is not None for r, _ in runs)]
    values = [[_value(c, r) for r, _ in runs] for c in numeric]
    rows = tuple(
        SeedRow(
            record.seed,
            tuple(_cell(v[i]) for v in values) + (_stop_reason(record), run.verdict),
        )
        for i, (record, run) in enumerate(runs)
    )
    return SeedSummary(
        columns=tuple(c.column for c in numeric) + TEXT,
        rows=rows,
        mean=tuple(_mean(v) for v in values) + (Mean("", ""),) * len(TEXT),
        over=count(len(runs), "seed"),
    )


def _value(column: _Numeric, record: RecordV1) -> float | int | None:
    value = column.read(record)
    return value if isinstance(value, (int, float)) and not isinstance(value, bool) else None


def _cell(value: float | int | None) -> str:
    return MISSING if value is None else number(value)


def _stop_reason(record: RecordV1) -> str:
    training = record.training
    found = getattr(training, "stop_reason", None) or getattr(training, "stopped_by", None)
    return found or NOT_RECORDED


def _mean(values: list[float | int | None]) -> Mean:
    present = [float(v) for v in values if v is not None]
    if not present:
        return Mean(MISSING, "")
    low, high = mean_interval(present)
    return Mean(*metric_parts(float(np.mean(present)), low, high))

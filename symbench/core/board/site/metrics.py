"""Every evaluator's metrics as an entry page shows them: a short table of readable values,
lists and nested results summarised (a closed-loop result is some 5,000 characters of JSON,
its per-reference lists among them), beside the metrics as the record holds them, at full
precision, for the reader who checks a number."""

from __future__ import annotations

import json
from dataclasses import dataclass
from typing import Any

from symbench.core.board.cells import count, number

SHORT_LIST = 4  # lists of numbers up to this long are shown whole: gains, fractions, intervals


@dataclass(frozen=True)
class EvaluatorMetrics:
    evaluator: str
    title: str  # "45 metrics of closed-loop"
    rows: tuple[tuple[str, str], ...]  # (label, value) in the record's order
    raw: str  # the record's metrics of this evaluator, as JSON: a line per metric


def evaluator_metrics(metrics: dict[str, dict[str, Any]]) -> tuple[EvaluatorMetrics, ...]:
    return tuple(
        EvaluatorMetrics(
            evaluator,
            f"{count(len(values), 'metric')} of {evaluator}",
            tuple(row for name, value in values.items() for row in _rows(name, value, True)),
            _raw(values),
        )
        for evaluator, values in metrics.items()
    )


def _raw(values: dict[str, Any]) -> str:
    """JSON with a line per metric, each compact: readable, and a fraction of the size of
    indenting every list item (pages hold three seeds of every evaluator)."""
    lines = (f"{json.dumps(name)}: {json.dumps(value)}" for name, value in values.items())
    return "{\n" + ",\n".join(lines) + "\n}"


def _rows(label: str, value: Any, top: bool) -> list[tuple[str, str]]:
    """A metric's rows: a mapping at the top level opens into a row per field; deeper
    mappings and lists of mappings (a row per reference) are summarised by field."""
    if isinstance(value, dict):
        if not top:
            return [(label, f"{count(len(value), 'field')}: {', '.join(value)}")]
        return [row for name, v in value.items() for row in _rows(f"{label} · {name}", v, False)]
    if isinstance(value, list) and value and all(isinstance(v, dict) for v in value):
        fields = {name: [entry.get(name) for entry in value] for entry in value for name in entry}
        return [(label, count(len(value), "entry", "entries"))] + [
            (f"{label} · {name}", shown(column))
            for name, column in fields.items()
            if _numbers(column)
        ]
    return [(label, shown(value))]


def shown(value: Any) -> str:
    """A value in a cell; a list of numbers longer than SHORT_LIST as its count, mean, min and
    max, a list of anything else as its count and how many differ."""
    if value is None:
        return "none"
    if isinstance(value, bool):
        return str(value).lower()
    if isinstance(value, (int, float)):
        return number(value)
    if isinstance(value, str):
        return value
    return _summary(value)


def _summary(values: list[Any]) -> str:
    numbers = _numbers(values)
    if not numbers:
        distinct = len({json.dumps(v, sort_keys=True) for v in values})
        return f"{count(len(values), 'value')}, {distinct} distinct" if values else "0 values"
    if len(values) <= SHORT_LIST and len(numbers) == len(values):
        return f"[{', '.join(number(v) for v in numbers)}]"
    missing = len(values) - len(numbers)
    return (
        f"{count(len(numbers), 'value')}{f' ({missing} none)' if missing else ''}: "
        f"mean {number(sum(numbers) / len(numbers))}, "
        f"min {number(min(numbers))}, max {number(max(numbers))}"
    )


def _numbers(values: list[Any]) -> list[float]:
    """The numbers of `values` when all the others are None (missing), else none."""
    numbers = [v for v in values if isinstance(v, (int, float)) and not isinstance(v, bool)]
    present = [v for v in values if v is not None]
    return numbers if numbers and len(numbers) == len(present) else []

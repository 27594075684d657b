"""`symbench tune summarize`: the `symbench tune` summaries of a folder as the board's tuning
table (robot x model: the chosen rate, the validation loss per rate, the best width, whether
the choice is on the edge of the rates tried, the data and commit) and as the lines of
`tuned_rates.toml`, so that what the searches found reaches the runs and the board without
copying by hand.

The rate chosen is the best at width scale 1: runs train the models at their default sizes
(only the learning rate is tuned per robot), and the best rate of another width need not be
the best at these."""

from __future__ import annotations

import json
from collections.abc import Callable
from pathlib import Path
from typing import Any

from symbench.core.common.errors import SymbenchError
from symbench.core.common.jsonfile import read_json
from symbench.core.runs.tune import on_edge
from symbench.core.runs.tune_journal import malformed_trial

COLUMNS = (
    "robot",
    "model",
    "backend",
    "dataset",
    "split",
    "chosen rate",
    "validation loss per rate at width scale 1 (chosen in bold)",
    "chosen rate on the edge",
    "best of all widths: rate, width scale (sizes), loss",
    "complete",
    "commit",
)
RUN_SCALE = 1.0  # the width scale of the models' default sizes, which runs train


SUMMARY_KEYS = ("robot", "model", "backend", "dataset", "trials", "best")


def read_summaries(folder: Path) -> list[dict[str, Any]]:
    """Every `*.tune.json` of `folder` that holds a best trial, by robot, model and backend;
    one that is no summary is refused, naming it."""
    paths = sorted(Path(folder).glob("*.tune.json"))
    if not paths:
        raise SymbenchError(f"{folder} holds no `symbench tune` summary (*.tune.json)")
    summaries = []
    for path in paths:
        summary = read_json(path, "tuning summary")
        why = _malformed(summary)
        if why is not None:
            raise SymbenchError(f"tuning summary {path} {why}: not a `symbench tune` summary")
        if summary["best"] is not None:  # None: a search that has finished no trial yet
            summaries.append(summary)
    return sorted(summaries, key=lambda s: (s["robot"], s["model"], s["backend"]))


def _malformed(summary: Any) -> str | None:
    """What makes `summary` no summary (None: nothing): a missing key, a name that is no
    text, a trial without the fields every finished trial holds, each of its type
    (`tune_journal.malformed_trial`)."""
    if not isinstance(summary, dict):
        return "is no JSON object"
    missing = [key for key in SUMMARY_KEYS if key not in summary]
    if missing:
        return f"has no '{missing[0]}'"
    names = [key for key in SUMMARY_KEYS[:4] if not isinstance(summary[key], str)]
    if names:
        return f"has {names[0]} {json.dumps(summary[names[0]])[:40]}, not a name"
    trials = summary["trials"]
    best = [] if summary["best"] is None else [summary["best"]]
    if not isinstance(trials, list):
        return "has trials that are no list"
    for trial in trials + best:
        why = malformed_trial(trial)
        if why is not None:
            return why
    if best and best[0] not in trials:
        return "has a best trial that is none of its trials"
    return None


def chosen(summary: dict[str, Any]) -> dict[str, Any] | None:
    """The summary's best trial at the default sizes (RUN_SCALE); None without one there."""
    trials = _at_run_scale(summary)
    return min(trials, key=lambda t: t["best_val_loss"]) if trials else None


def _at_run_scale(summary: dict[str, Any]) -> list[dict[str, Any]]:
    return [t for t in summary["trials"] if t["width_scale"] == RUN_SCALE]


def markdown(summaries: list[dict[str, Any]]) -> str:
    """The board's table: a row per summary."""
    lines = [
        f"| {' | '.join(COLUMNS)} |",
        f"|{'---|' * len(COLUMNS)}",
        *(f"| {' | '.join(_row(s))} |" for s in summaries),
    ]
    return "\n".join(lines) + "\n"


def _row(summary: dict[str, Any]) -> list[str]:
    choice, best = chosen(summary), summary["best"]
    losses = "; ".join(
        _bold(f"{t['learning_rate']:g}: {t['best_val_loss']:.3g}", t == choice)
        for t in _at_run_scale(summary)
    )
    sizes = ", ".join(f"{k} {v}" for k, v in best["hyper"].items())
    return [
        summary["robot"],
        summary["model"],
        summary["backend"],
        summary["dataset"],
        str(summary.get("split", "")),
        "-" if choice is None else f"{choice['learning_rate']:g}",
        losses or "-",
        "-" if choice is None else _yes(on_edge(_at_run_scale(summary), choice)),
        f"{best['learning_rate']:g}, {best['width_scale']:g}"
        + (f" ({sizes})" if sizes else "")
        + f": {best['best_val_loss']:.3g}",
        _yes(bool(summary.get("complete"))),
        str(summary.get("git_commit") or "")[:7],
    ]


def _bold(text: str, bold: bool) -> str:
    return f"**{text}**" if bold else text


def _yes(flag: bool) -> str:
    return "yes" if flag else "no"


def toml_lines(summaries: list[dict[str, Any]]) -> str:
    """The `[model.backend]` tables of `tuned_rates.toml`: each robot's chosen rate (of several
    summaries of one robot, model and backend: the one of lowest validation loss), with a
    comment where it cannot be trusted yet."""
    picked: dict[tuple[str, str, str], tuple[dict[str, Any], dict[str, Any]]] = {}
    for summary in summaries:
        choice = chosen(summary)
        key = (summary["model"], summary["backend"], summary["robot"])
        if choice is not None and (
            key not in picked or choice["best_val_loss"] < picked[key][1]["best_val_loss"]
        ):
            picked[key] = (summary, choice)
    lines: list[str] = []
    for (model, backend, robot), (summary, choice) in sorted(picked.items()):
        if f"[{model}.{backend}]" not in lines:
            lines += [*([""] if lines else []), f"[{model}.{backend}]"]
        doubts = {
            "on the edge of the rates tried": on_edge(_at_run_scale(summary), choice),
            "search not complete": not summary.get("complete"),
        }
        notes = "; ".join(why for why, doubt in doubts.items() if doubt)
        lines.append(f"{robot} = {choice['learning_rate']!r}" + (f"  # {notes}" if notes else ""))
    return "\n".join(lines) + "\n"


def summarize(folder: Path, out: Path | None, report: Callable[[str], None]) -> None:
    """Reports the table and the TOML lines of `folder`'s summaries; writes the table to
    `out` when given."""
    summaries = read_summaries(folder)
    table = markdown(summaries)
    if out is not None:
        Path(out).parent.mkdir(parents=True, exist_ok=True)
        Path(out).write_text(table)
    report(table)
    report("# the lines for symbench/plugins/tuned_rates.toml (the rates at width scale 1)")
    report(toml_lines(summaries))

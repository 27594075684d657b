"""What a board cost to make: the summed wall time its records report (dataset, training,
the retrainings their evaluators asked for, evaluation), per dataset and model entry
(named as summary.md names it: with variant and backend where a model has several).

A run trains and simulates on one thread (torch's setting here, and every sweep worker's),
so these hours are core-hours, the figure a reader needs to plan a rerun or a cluster job;
on a machine shared with other work they overstate it. A training that
several runs share (`symbench sweep`'s retrainings) is counted where it was made: the run
that loaded it reports the load, seconds at most. Records made since 2026-12-07 also count
the run's CPU seconds and time each evaluator (`runs.timing`): a second table sums those.
"""

from __future__ import annotations

from collections import defaultdict
from pathlib import Path

import pandas as pd

from symbench.core.board.summary import model_labels
from symbench.core.runs.results import RecordV1
from symbench.core.runs.timing import CPU_KEY, STAGES, evaluator_of


def _hours(seconds: float) -> str:
    return f"{seconds / 3600:.2f}"


def cost_section(records: list[tuple[Path, RecordV1]]) -> list[str]:
    """The Markdown section of summary.md: one row per dataset, hours by part and by model."""
    entries = pd.DataFrame(
        [(r.model.name, r.model.variant, r.model.backend) for _, r in records],
        columns=["model", "variant", "backend"],
    )
    labels = model_labels(entries) if len(entries) else pd.Series(dtype=str)
    by_dataset: dict[str, dict[str, float]] = defaultdict(lambda: defaultdict(float))
    by_model: dict[str, dict[str, float]] = defaultdict(lambda: defaultdict(float))
    runs: dict[str, int] = defaultdict(int)
    for (_, record), label in zip(records, labels, strict=True):
        did = record.dataset.id
        runs[did] += 1
        for part in STAGES:
            seconds = float(record.timings_s.get(part, 0.0))
            by_dataset[did][part] += seconds
            by_model[did][label] += seconds
    models = sorted({m for per_model in by_model.values() for m in per_model})
    lines = [
        "# What this board cost",
        "",
        "Hours of wall time the records report, summed; a training that runs share counts "
        "once, where it was made. A run trains and simulates on one thread, so these are "
        "core-hours where no more runs than cores shared the machine; a run beside other work, "
        "or waiting for another run's training (counted as retraining), reports more than it "
        "computed.",
        "",
        "| dataset | runs | training | retraining | evaluation | total | "
        + " | ".join(models)
        + " |",
        "|---|---|---|---|---|---|" + "---|" * len(models),
    ]
    for did in sorted(runs):
        parts = by_dataset[did]
        total = sum(parts.values())
        lines.append(
            f"| {did} | {runs[did]} | {_hours(parts['dataset_s'] + parts['training_s'])} | "
            f"{_hours(parts['retraining_s'])} | {_hours(parts['evaluation_s'])} | "
            f"{_hours(total)} | "
            + " | ".join(_hours(by_model[did][m]) if m in by_model[did] else "-" for m in models)
            + " |"
        )
    return lines + [""] + _measured_section([r for _, r in records])


def _measured_section(records: list[RecordV1]) -> list[str]:
    """Per dataset, the records that count CPU seconds: their wall and CPU hours and the
    evaluation's hours by evaluator; nothing when no record counts them."""
    timed = [r for r in records if CPU_KEY in r.timings_s]
    if not timed:
        return []
    names = sorted({n for r in timed for k in r.timings_s if (n := evaluator_of(k))})
    sums: dict[str, dict[str, float]] = defaultdict(lambda: defaultdict(float))
    for record in timed:
        row, timings = sums[record.dataset.id], record.timings_s
        row["runs"] += 1
        row["wall"] += sum(float(timings.get(part, 0.0)) for part in STAGES)
        row["cpu"] += float(timings[CPU_KEY])
        row["evaluation"] += float(timings.get("evaluation_s", 0.0))
        for key, seconds in timings.items():
            if name := evaluator_of(key):
                row[f"evaluator {name}"] += float(seconds)
    lines = [
        "Runs whose records also count their CPU seconds (user and system, their worker "
        "processes included: less than the wall time when other work shared the cores, more "
        "when a run trained ahead in parallel) and time each evaluator, without the trainings "
        "it asked for; hours:",
        "",
        "| dataset | runs | wall | CPU | evaluation | " + " | ".join(names) + " |",
        "|---|---|---|---|---|" + "---|" * len(names),
    ]
    for did in sorted(sums):
        row = sums[did]
        lines.append(
            f"| {did} | {int(row['runs'])} | {_hours(row['wall'])} | {_hours(row['cpu'])} | "
            f"{_hours(row['evaluation'])} | "
            + " | ".join(_hours(row[f"evaluator {n}"]) for n in names)
            + " |"
        )
    return lines + [""]

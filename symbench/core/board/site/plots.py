"""A board page's plots, drawn into the site as PNG: the sample-efficiency curve (the
Markdown board's own plot) and the closed loop's headline metric per split. A plot without
data is absent, and its caption says why."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import pandas as pd

from symbench.core.board.leaderboard import COLUMNS, sample_efficiency_plot, spread
from symbench.core.board.plots import Spread, grouped_bars_png
from symbench.core.board.site import names
from symbench.core.board.summary import split_order

# the closed loop's headline, best first: the score between the PD alone (0) and the
# expert's feedforward (1), else the seconds held, both at the headline PD fraction
CLOSED_LOOP_HEADLINES = (
    ("closed-loop", "pd_normalized_score"),
    ("closed-loop", "pd_time_to_failure_s"),
)


@dataclass(frozen=True)
class Plot:
    title: str
    path: str | None  # the PNG, relative to the site's root; None when there is no data
    caption: str  # what the plot shows, or why it is absent


def draw_plots(rows: pd.DataFrame, robot: str, dataset: str, site: Path) -> tuple[Plot, ...]:
    """The plots of one board page (the aggregate's `rows` of one robot and dataset)."""
    return (
        _sample_efficiency(rows, robot, dataset, site),
        _closed_loop(rows, robot, dataset, site),
    )


def _sample_efficiency(rows: pd.DataFrame, robot: str, dataset: str, site: Path) -> Plot:
    title = "Sample efficiency"
    path = names.plot_file(robot, dataset, "sample-efficiency")
    if not sample_efficiency_plot(rows, robot, site / path):
        return Plot(title, None, "No plot: no record of a fraction-F split on this dataset.")
    return Plot(
        title,
        path,
        "Test torque RMSE (mean, 95 % bootstrap interval and each seed's value) against the "
        "fraction of training trajectories; iid is the fraction 1.",
    )


def _closed_loop(rows: pd.DataFrame, robot: str, dataset: str, site: Path) -> Plot:
    title = "Closed loop"
    for evaluator, metric in CLOSED_LOOP_HEADLINES:
        column = COLUMNS.get((evaluator, metric))
        if column is None or f"{column}_mean" not in rows:
            continue
        measured = rows[rows[f"{column}_mean"].notna()]
        if measured.empty:
            continue
        path = names.plot_file(robot, dataset, "closed-loop")
        grouped_bars_png(
            _bars(measured, column),
            f"{metric} (mean, 95 % CI, seeds)",
            f"{robot}, {dataset}: closed loop",
            site / path,
        )
        return Plot(
            title,
            path,
            f"Each model's closed-loop {metric} per split (the {evaluator} evaluator at "
            "the headline PD fraction).",
        )
    return Plot(
        title, None, "No plot: no record on this dataset has closed-loop metrics (run --full)."
    )


def _bars(rows: pd.DataFrame, column: str) -> dict[str, dict[str, Spread]]:
    """split -> model label -> its spread over seeds; the protocol joins the label when
    there are several, so that no two rows share a bar."""
    protocols = rows.protocol.nunique() > 1
    groups: dict[str, dict[str, Spread]] = {}
    for split in sorted(rows.split.unique(), key=split_order):
        groups[split] = {
            f"{r.model} ({r.variant}, {r.backend}"
            + (f", {r.protocol}" if protocols else "")
            + ")": spread(r, column)
            for _, r in rows[rows.split == split].iterrows()
        }
    return groups

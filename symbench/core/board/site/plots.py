"""A board page's plots, drawn into the site as SVG: the sample-efficiency curve (the
Markdown board's own plot, from the same series), the closed loop's headline metric per
split, and each model's generalization gap (`gap`). A plot without data is absent, and its
caption says why; a drawn plot's alt text says what it shows and its result."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import pandas as pd

from symbench.core.board.gap import HELD_OUT_SPLITS, generalization_gaps
from symbench.core.board.leaderboard import COLUMNS
from symbench.core.board.plot_files import write_svg
from symbench.core.board.plots import bars_figure, sample_efficiency_figure
from symbench.core.board.series import sample_efficiency_panels, split_bars
from symbench.core.board.site import names
from symbench.core.board.site.alt_text import ranking

# the closed loop's headline, best first, with its axis label: the tracking score (v7's
# headline, as in the summary and the claims), else the score of the time held, both between
# the PD alone (0) and the expert's feedforward (1), else the seconds held, all at the
# headline PD fraction; higher is better for each
CLOSED_LOOP_HEADLINES = (
    ("closed-loop", "pd_tracking_score", "tracking score (0 = PD alone, 1 = expert)"),
    ("closed-loop", "pd_normalized_score", "closed-loop score (0 = PD alone, 1 = expert)"),
    ("closed-loop", "pd_time_to_failure_s", "seconds held on the wall (closed loop)"),
)


@dataclass(frozen=True)
class Plot:
    title: str
    path: str | None  # the SVG, relative to the site's root; None when there is no data
    caption: str  # what the plot shows, or why it is absent
    alt: str = ""  # the plot's result in a sentence, for readers who cannot see it


def draw_plots(rows: pd.DataFrame, robot: str, dataset: str, site: Path) -> tuple[Plot, ...]:
    """The plots of one board page (the aggregate's `rows` of one robot and dataset)."""
    return (
        _sample_efficiency(rows, robot, dataset, site),
        _closed_loop(rows, robot, dataset, site),
        *(_generalization_gap(rows, robot, dataset, site, split) for split in HELD_OUT_SPLITS),
    )


def _sample_efficiency(rows: pd.DataFrame, robot: str, dataset: str, site: Path) -> Plot:
    title = "Sample efficiency"
    panels = sample_efficiency_panels(rows, robot)  # one: the page's rows are one dataset's
    if not panels:
        return Plot(title, None, "No plot: no record of a fraction-F split on this dataset.")
    path = names.plot_file(robot, dataset, "sample-efficiency")
    write_svg(sample_efficiency_figure(panels), site / path)
    (series,) = panels.values()
    fractions = sorted({x for s in series for x in s.points})
    result = ranking(series, fractions, "fraction", "lowest error", "highest error", True)
    return Plot(
        title,
        path,
        "Test torque RMSE (mean, 95 % bootstrap interval and each seed's value) against the "
        "fraction of training climbs; iid is the fraction 1. A line breaks where its entry "
        "has no record.",
        f"Test torque RMSE against the fraction of training climbs. {result}",
    )


def _closed_loop(rows: pd.DataFrame, robot: str, dataset: str, site: Path) -> Plot:
    title = "Closed loop"
    for evaluator, metric, label in CLOSED_LOOP_HEADLINES:
        column = COLUMNS.get((evaluator, metric))
        if column is None or f"{column}_mean" not in rows:
            continue
        measured = rows[rows[f"{column}_mean"].notna()]
        if measured.empty:
            continue
        path = names.plot_file(robot, dataset, "closed-loop")
        series, splits = split_bars(measured, column)
        write_svg(bars_figure(series, splits, label, f"{robot}: closed loop"), site / path)
        result = ranking(series, splits, "split", "highest", "lowest", False)
        return Plot(
            title,
            path,
            f"Each model's {label} per split (mean, 95 % bootstrap interval and each seed's "
            f"value; the {evaluator} evaluator at the headline PD fraction).",
            f"The {label} per split. {result}",
        )
    return Plot(
        title, None, "No plot: no record on this dataset has closed-loop metrics (run --full)."
    )


def _generalization_gap(
    rows: pd.DataFrame, robot: str, dataset: str, site: Path, held_out: str
) -> Plot:
    # the first held-out split's plot keeps the file name it had before the second came
    first = held_out == HELD_OUT_SPLITS[0]
    title = "Generalization gap" + ("" if first else f", {held_out}")
    gaps = generalization_gaps(rows, held_out)
    if gaps is None:
        return Plot(
            title,
            None,
            f"No plot: no model has records of both {held_out} and its control or iid "
            "on this dataset.",
        )
    path = names.plot_file(robot, dataset, "generalization-gap" + ("" if first else f"-{held_out}"))
    label = f"test RMSE on {held_out} / on {gaps.control}"
    figure = bars_figure(gaps.series, gaps.protocols, label, f"{robot}: generalization gap", 1.0)
    write_svg(figure, site / path)
    result = ranking(gaps.series, gaps.protocols, "protocol", "smallest gap", "largest gap", True)
    what = "rotations" if held_out == "unseen-rotation" else "slope headings"
    return Plot(
        title,
        path,
        f"Each model's test RMSE on {held_out} over its test RMSE on {gaps.control}, seed by "
        "seed (mean, 95 % bootstrap interval and each seed's ratio), per training protocol; "
        f"1 (dashed): the unseen {what} cost nothing."
        + (
            ""
            if gaps.control != "iid"
            else " No record of the size-matched control: iid trains on more climbs, so "
            "this ratio overstates the gap."
        ),
        f"The ratio of test RMSE on {held_out} to {gaps.control} per protocol. {result}",
    )

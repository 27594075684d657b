"""The leaderboard's headline page: every model side by side, one row per dataset and split.

The per-robot pages rank models within one dataset and split; the claims a reader checks
(does a model generalize to unseen rotations, does it degrade as legs increase, does it keep
the robot on the wall) need the models in columns across splits and datasets (a standard
dataset id names its robot, e.g. hexa-climb-small-v5), so this page puts them there.
"""

from __future__ import annotations

import pandas as pd

from symbench.core.board.cells import cell_of, metric_cell
from symbench.core.board.sizes import by_size, miss_caption, titled
from symbench.core.board.statistics import RESAMPLES, Interval, across_tasks

SPLIT_ORDER = ("iid", "unseen-heading", "unseen-rotation", "orbit-rotation")


def split_order(split: str) -> tuple[int, float, str]:
    """iid and the unseen splits first, then the fractions in increasing order."""
    if split in SPLIT_ORDER:
        return (0, SPLIT_ORDER.index(split), split)
    if split.startswith("fraction-"):
        return (1, float(split.removeprefix("fraction-")), split)
    return (2, 0.0, split)


def model_labels(table: pd.DataFrame) -> pd.Series:
    """The model's name, with variant and backend when a model appears with several."""
    combos = table.groupby("model")[["variant", "backend"]].nunique().max(axis=1)
    return table.apply(
        lambda r: r.model if combos[r.model] == 1 else f"{r.model} ({r.variant}, {r.backend})",
        axis=1,
    )


def _column_order(table: pd.DataFrame) -> list[str]:
    """Models by their mean rank over all (dataset, split) groups, then by name."""
    mean_rank = table.groupby("label")["rank"].mean()
    return sorted(mean_rank.index, key=lambda label: (mean_rank[label], label))


def error_section(table: pd.DataFrame, metric: str, title: str) -> list[str]:
    """One error metric per dataset and split, models in columns."""
    columns = _column_order(table)
    lines = [
        f"## {title}",
        "",
        "| dataset | split | " + " | ".join(columns) + " |",
        "|---|---|" + "---|" * len(columns),
    ]
    groups = table.groupby(["dataset", "split"], sort=False)
    for did, split in sorted(groups.groups, key=lambda k: (k[0], split_order(k[1]))):
        part = groups.get_group((did, split)).set_index("label")
        cells = [cell_of(part.loc[c], metric, 3) if c in part.index else "-" for c in columns]
        lines.append(f"| {did} | {split} | " + " | ".join(cells) + " |")
    return lines + [""]


def closed_loop_section(table: pd.DataFrame) -> list[str]:
    """The closed loop at the headline PD fraction: the model's score between the PD alone
    (0) and the oracle (1), and the seconds it held the reference. The score is the
    continuous tracking score where the records have it (pushed references, dataset v7
    on), else the score of time held (earlier records)."""
    if "cl_held_s_mean" not in table or table.cl_held_s_mean.isna().all():
        return []
    rows = table[table.cl_held_s_mean.notna()]
    tracking = "cl_tracking_mean" in rows and rows.cl_tracking_mean.notna().all()
    score = "cl_tracking" if tracking else "cl_score"
    name = "tracking score" if tracking else "normalized score"
    columns = _column_order(rows)
    lines = [
        f"## Closed loop at the headline PD fraction: {name} (floor 0, oracle 1), "
        "mean [95 % CI] over seeds / seconds held, mean over seeds",
        "",
        "| dataset | split | " + " | ".join(columns) + " |",
        "|---|---|" + "---|" * len(columns),
    ]
    for (did, split), part in rows.groupby(["dataset", "split"], sort=True):
        part = part.set_index("label")
        cells = [
            f"{cell_of(part.loc[c], score, 2)} / {part.at[c, 'cl_held_s_mean']:.3g}"
            if c in part.index
            else "-"
            for c in columns
        ]
        lines.append(f"| {did} | {split} | " + " | ".join(cells) + " |")
    return lines + [""]


def aggregate_section(table: pd.DataFrame) -> list[str]:
    """One protocol's models that ran on every dataset and split of the board, over the
    pairs where they share at least two seeds: the interquartile mean of normalized errors
    and the probability of improvement, with stratified bootstrap intervals
    (`statistics.across_tasks`). An entry run on only some pairs (a second backend on one
    robot) is named and left out, so it neither empties the aggregate nor skews it."""
    groups = table.groupby(["dataset", "split"], sort=True)
    coverage = table.drop_duplicates(["label", "dataset", "split"]).groupby("label").size()
    order = _column_order(table)
    columns = [c for c in order if coverage[c] == groups.ngroups]
    partial = [c for c in order if c not in columns]
    tasks = []
    for _, part in groups:
        rmse = {r.label: r.per_seed["rmse_Nm"] for _, r in part.iterrows()}
        by_seed = pd.DataFrame(rmse)[columns].dropna()
        tasks += [by_seed] if len(by_seed) >= 2 else []
    if len(columns) < 2 or len(tasks) < 2:
        return []
    result = across_tasks(tasks)
    left_out = (
        " Left out, as they ran on only some pairs: "
        + ", ".join(f"{c} ({coverage[c]} of {groups.ngroups})" for c in partial)
        + "."
        if partial
        else ""
    )
    lines = [
        "## Aggregate over datasets and splits: normalized test RMSE",
        "",
        "A seed's normalized error is its test RMSE over the lowest mean test RMSE of any "
        f"model on the same dataset and split (1: that best mean). Over the {result.tasks} "
        f"of {groups.ngroups} (dataset, split) pairs where the models that ran on every pair "
        f"share at least two seeds, {result.seeds} (pair, seed) values per model; 95 % "
        f"stratified bootstrap intervals ({RESAMPLES} resamples of the seeds within each "
        f"pair).{left_out}",
        "",
        "| model | interquartile mean [95 % CI] |",
        "|---|---|",
    ]
    for label in columns:
        iqm = result.iqm[label]
        lines.append(f"| {label} | {metric_cell(iqm.value, iqm.low, iqm.high, 3)} |")
    lines += [
        "",
        "Probability of improvement: the chance that the row's model has a lower test RMSE "
        "than the column's on the same seed of a pair (a tie counts one half), averaged over "
        "the pairs [95 % CI].",
        "",
        "| P(row better) | " + " | ".join(columns) + " |",
        "|---|" + "---|" * len(columns),
    ]
    for x in columns:
        cells = [_probability(result.improvement[x, y]) if x != y else "-" for y in columns]
        lines.append(f"| {x} | " + " | ".join(cells) + " |")
    return lines + [""]


def _probability(p: Interval) -> str:
    return f"{p.value:.2f} [{p.low:.2f}, {p.high:.2f}]"


def headline(table: pd.DataFrame) -> str:
    """The Markdown of summary.md from an aggregated table (see `leaderboard.aggregate`):
    the sections once per training protocol and size (default first), never mixing them."""
    seeds = sorted(int(s) for s in table.seeds.unique())
    lines = [
        "# Leaderboard summary",
        "",
        f"Seeds per run group: {', '.join(map(str, seeds))}. Every mean comes with its 95 % "
        "bootstrap interval over seeds [low, high]. Rank within each dataset and split is by "
        "mean test RMSE; the per-robot pages have every metric and the rank bands "
        "(docs/leaderboard-protocol.md#statistics).",
        "",
    ]
    sections = [
        (protocol, size, part)
        for protocol, by_protocol in table.groupby("protocol", sort=True)
        for size, part in by_size(by_protocol)
    ]
    for protocol, size, part in sections:
        part = part.assign(label=model_labels(part))
        lines += [titled(f"# Trained under the {protocol} protocol", size), ""]
        caption = miss_caption(part, size)
        lines += [caption, ""] if caption else []
        lines += error_section(part, "rmse_Nm", "Test torque RMSE (N m), mean [95 % CI] over seeds")
        lines += error_section(
            part,
            "nrmse",
            "Normalized test RMSE (RMSE / std of the test torques), comparable across robots",
        )
        lines += aggregate_section(part)
        lines += closed_loop_section(part)
    return "\n".join(lines)

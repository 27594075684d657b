"""The leaderboard's headline page: every model side by side, one row per dataset and split.

The per-robot pages rank models within one dataset and split; the claims a reader checks
(does a model generalize to unseen rotations, does it degrade as legs increase, does it keep
the robot on the wall) need the models in columns across splits and datasets (a standard
dataset id names its robot, e.g. hexa-climb-small-v5), so this page puts them there.
"""

from __future__ import annotations

import numpy as np
import pandas as pd

SPLIT_ORDER = ("iid", "unseen-heading", "unseen-rotation", "orbit-rotation")


def split_order(split: str) -> tuple[int, float, str]:
    """iid and the unseen splits first, then the fractions in increasing order."""
    if split in SPLIT_ORDER:
        return (0, SPLIT_ORDER.index(split), split)
    if split.startswith("fraction-"):
        return (1, float(split.removeprefix("fraction-")), split)
    return (2, 0.0, split)


def _labels(table: pd.DataFrame) -> pd.Series:
    """The model's name, with variant and backend when a model appears with several."""
    combos = table.groupby("model")[["variant", "backend"]].nunique().max(axis=1)
    return table.apply(
        lambda r: r.model if combos[r.model] == 1 else f"{r.model} ({r.variant}, {r.backend})",
        axis=1,
    )


def _cell(mean: float, std: float, digits: int = 3) -> str:
    if np.isnan(mean):
        return "-"
    return f"{mean:.{digits}g}" if np.isnan(std) else f"{mean:.{digits}g} ± {std:.2g}"


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
        cells = [
            _cell(part.at[c, f"{metric}_mean"], part.at[c, f"{metric}_std"])
            if c in part.index
            else "-"
            for c in columns
        ]
        lines.append(f"| {did} | {split} | " + " | ".join(cells) + " |")
    return lines + [""]


def closed_loop_section(table: pd.DataFrame) -> list[str]:
    """The closed loop at the headline PD fraction: the model's score between the PD alone
    (0) and the expert's recorded feedforward (1), and the seconds it held the reference."""
    if "cl_score_mean" not in table or table.cl_held_s_mean.isna().all():
        return []
    rows = table[table.cl_held_s_mean.notna()]
    columns = _column_order(rows)
    lines = [
        "## Closed loop at the headline PD fraction: normalized score (floor 0, oracle 1) "
        "/ seconds held, mean over seeds",
        "",
        "| dataset | split | " + " | ".join(columns) + " |",
        "|---|---|" + "---|" * len(columns),
    ]
    for (did, split), part in rows.groupby(["dataset", "split"], sort=True):
        part = part.set_index("label")
        cells = [
            f"{_cell(part.at[c, 'cl_score_mean'], part.at[c, 'cl_score_std'], 2)} / "
            f"{part.at[c, 'cl_held_s_mean']:.3g}"
            if c in part.index
            else "-"
            for c in columns
        ]
        lines.append(f"| {did} | {split} | " + " | ".join(cells) + " |")
    return lines + [""]


def headline(table: pd.DataFrame) -> str:
    """The Markdown of summary.md from an aggregated table (see `leaderboard.aggregate`):
    the sections once per training protocol, never mixing them."""
    seeds = sorted(int(s) for s in table.seeds.unique())
    lines = [
        "# Leaderboard summary",
        "",
        f"Seeds per run group: {', '.join(map(str, seeds))}. Rank within each dataset and "
        "split is by mean test RMSE; the per-robot pages have every metric.",
        "",
    ]
    for protocol, part in table.groupby("protocol", sort=True):
        part = part.assign(label=_labels(part))
        lines += [f"# Trained under the {protocol} protocol", ""]
        lines += error_section(part, "rmse_Nm", "Test torque RMSE (N m), mean ± std over seeds")
        lines += error_section(
            part,
            "nrmse",
            "Normalized test RMSE (RMSE / std of the test torques), comparable across robots",
        )
        lines += closed_loop_section(part)
    return "\n".join(lines)

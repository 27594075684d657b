"""The aggregate table's rows (`leaderboard.aggregate`) as the plots' series: one per model
entry, its points the metric's spread over seeds at each x or group. The Markdown board and
the site draw the same series, so their plots never disagree."""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
import pandas as pd

from symbench.core.board.plots import Series, Spread
from symbench.core.board.summary import split_order
from symbench.core.robot.specs import split_variant

ENTRY = ["model", "variant", "backend"]


def spread(row: pd.Series, metric: str) -> Spread:
    """A metric of an aggregate row as the plots draw it: mean, interval, each seed."""
    values = [v for v in row.per_seed[metric].values() if not np.isnan(v)]
    return Spread(
        float(row[f"{metric}_mean"]),
        float(row[f"{metric}_ci_low"]),
        float(row[f"{metric}_ci_high"]),
        tuple(values),
    )


def label_of(row: pd.Series, extra: Sequence[str] = ()) -> str:
    """'sdnn (acc, torch)', with the `extra` columns' values after the backend."""
    return f"{row.model} ({', '.join([row.variant, row.backend, *(row[c] for c in extra)])})"


def several(rows: pd.DataFrame, columns: Sequence[str]) -> list[str]:
    """The `columns` that take more than one value in `rows`: those a label must name."""
    return [c for c in columns if rows[c].nunique() > 1]


def _curves(rows: pd.DataFrame, x: str, keys: list[str], extra: list[str]) -> list[Series[float]]:
    """A series of test RMSE against column `x` per group of `keys` (the model's first, so
    that a model's entries sit together in the legend)."""
    series = []
    for _, part in rows.groupby(keys, sort=True):
        first = part.iloc[0]
        points = {float(r[x]): spread(r, "rmse_Nm") for _, r in part.sort_values(x).iterrows()}
        series.append(Series(str(first.model), label_of(first, extra), points))
    return series


def sample_efficiency_series(table: pd.DataFrame, robot: str) -> list[Series[float]]:
    """Test RMSE against training fraction, a series per model entry (and dataset and
    protocol, when the robot has several); none without fractions. `iid` is the same split
    with all of its training climbs, so it is the point at 1; an entry with that point
    alone (run on `iid` only, as the board's JAX entries) is no curve and is left out."""
    rows = table[table.robot == robot]
    fractions = rows.split.str.startswith("fraction-")
    if not fractions.any():
        return []
    rows = rows[fractions | (rows.split == "iid")]
    rows = rows.assign(
        fraction=rows.split.str.removeprefix("fraction-").replace("iid", "1").astype(float)
    )
    extra = several(rows, ["dataset", "protocol"])
    curves = _curves(rows, "fraction", [*ENTRY, "dataset", "protocol"], extra)
    return [curve for curve in curves if len(curve.points) > 1]


def sample_efficiency_panels(table: pd.DataFrame, robot: str) -> dict[str, list[Series[float]]]:
    """`sample_efficiency_series` per dataset of `robot` that has a curve, by panel title:
    one dataset's fractions are not another's numbers of climbs, nor its test climbs the
    other's, so two datasets never share an axis. Where the robot has records on several
    datasets, each title names its dataset (and protocol, when it has one)."""
    rows = table[table.robot == robot]
    datasets = sorted(rows.dataset.unique())
    panels = {}
    for dataset in datasets:
        part = rows[rows.dataset == dataset]
        series = sample_efficiency_series(part, robot)
        if not series:
            continue
        protocols = part.protocol.unique()
        title = f"{robot}: sample efficiency"
        if len(datasets) > 1:
            title = dataset + (f", {protocols[0]} protocol" if len(protocols) == 1 else "")
        panels[title] = series
    return panels


def asymmetry_series(
    table: pd.DataFrame, base: str
) -> tuple[list[Series[float]], tuple[list[float], list[float]] | None]:
    """Test RMSE against the asymmetry of `base`'s variants (`base-asym-A`, `base` itself at
    0), a series per split and model entry (and preset and protocol, when several), with the
    datasets' own torque asymmetry; no series when `base` has no variant records, nor for a
    split or model run on the symmetric robot only."""
    rows = table.copy()
    rows[["base", "asymmetry"]] = [split_variant(r) for r in rows.robot]
    rows = rows[rows.base == base]
    varied = rows.groupby(["split", *ENTRY, "preset", "protocol"]).asymmetry.transform("max") > 0
    rows = rows[varied]
    if rows.empty:
        return [], None
    extra = ["split", *several(rows, ["preset", "protocol"])]
    series = _curves(rows, "asymmetry", [*ENTRY, "split", "preset", "protocol"], extra)
    data = None
    if "data_tau_asym_mean" in rows:
        measured = rows.dropna(subset=["data_tau_asym_mean"]).groupby("asymmetry")
        per_dataset = measured.data_tau_asym_mean.first()
        data = (per_dataset.index.tolist(), per_dataset.tolist())
    return series, data


def split_bars(rows: pd.DataFrame, column: str) -> tuple[list[Series[str]], list[str]]:
    """A metric per split (the groups, in the boards' split order) and model entry (and
    protocol, when several)."""
    extra = several(rows, ["protocol"])
    series = []
    for _, part in rows.groupby([*ENTRY, "protocol"], sort=True):
        first = part.iloc[0]
        points = {str(r.split): spread(r, column) for _, r in part.iterrows()}
        series.append(Series(str(first.model), label_of(first, extra), points))
    return series, sorted(rows.split.unique(), key=split_order)

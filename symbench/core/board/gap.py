"""The generalization gap of each model entry: its test RMSE on a held-out split
(`unseen-rotation`, `unseen-heading`) over its test RMSE on the split's size-matched control
(`control-rotation`, `control-heading`: as many training climbs, the same seed), seed by
seed; about 1 when the unseen orientations are no news to the model. Records without the
control are compared with `iid` instead, which trains on more climbs, so that ratio
overstates the gap; the plot names which one it divides by."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd

from symbench.core.board.plots import Series, Spread
from symbench.core.board.series import ENTRY, label_of
from symbench.core.board.statistics import mean_interval
from symbench.core.data.splits import control_of

HELD_OUT_SPLITS = ("unseen-rotation", "unseen-heading")  # a gap plot each


@dataclass(frozen=True)
class Gaps:
    """The gaps of one board page: a series per model entry, its points by protocol."""

    control: str  # the split the gap divides by
    series: list[Series[str]]
    protocols: list[str]


def ratio(held_out: dict[int, float], control: dict[int, float]) -> Spread | None:
    """The ratio of two entries' test RMSE on the seeds both have (a seed fixes the
    initialization, and for a control the draw of its climbs too): its mean, the bootstrap
    interval of that mean over the seeds, and each seed's ratio; None without a common seed
    (a control's RMSE of 0 gives no ratio)."""
    seeds = sorted(s for s in set(held_out) & set(control) if control[s] > 0)
    ratios = [held_out[s] / control[s] for s in seeds]
    if not ratios:
        return None
    low, high = mean_interval(ratios)
    return Spread(float(np.mean(ratios)), low, high, tuple(ratios))


def generalization_gaps(rows: pd.DataFrame, held_out: str = HELD_OUT_SPLITS[0]) -> Gaps | None:
    """The gaps on `held_out` of the aggregate's `rows` of one robot and dataset; None without
    records of `held_out` and of its control or iid for one model entry."""
    splits = set(rows.split)
    control = next((s for s in (control_of(held_out), "iid") if s in splits), None)
    if held_out not in splits or control is None:
        return None
    keys = [*ENTRY, "protocol"]
    base = {
        tuple(r[keys]): r.per_seed["rmse_Nm"] for _, r in rows[rows.split == control].iterrows()
    }
    models: dict[str, str] = {}  # label -> model
    points: dict[str, dict[str, Spread]] = {}  # label -> protocol -> gap
    for _, row in rows[rows.split == held_out].sort_values(keys).iterrows():
        other = base.get(tuple(row[keys]))
        found = None if other is None else ratio(row.per_seed["rmse_Nm"], other)
        if found is not None:
            models[label := label_of(row)] = str(row.model)
            points.setdefault(label, {})[str(row.protocol)] = found
    if not points:
        return None
    protocols = sorted({p for by_protocol in points.values() for p in by_protocol})
    return Gaps(control, [Series(models[k], k, v) for k, v in points.items()], protocols)

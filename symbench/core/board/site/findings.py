"""The overview's findings in plain words, written from one table's aggregate rows (never a
number typed in): per split, the best equivariant model against the best that is not (or the
two lowest, when the table lacks one kind), as a ratio of their errors with its paired
t-interval and whether that t-test over seeds tells them apart (`statistics.differ`, the
test of the rank bands); then the closed loop's highest and lowest score."""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
import pandas as pd

from symbench.core.board.cells import TIMES, cell_of, metric_cell
from symbench.core.board.site.columns import RMSE
from symbench.core.board.statistics import differ, t_interval
from symbench.core.board.summary import split_order
from symbench.core.common import portable_math

Label = Callable[[pd.Series], str]  # an aggregate row's model as the table names it


def findings(rows: pd.DataFrame, robot: str, score: str | None, label: Label) -> tuple[str, ...]:
    """The findings of one overview table: `rows` of one dataset and protocol, `score` the
    closed-loop column shown (None: none), `label` the row's name in the table."""
    if rows[["model", "variant", "backend"]].drop_duplicates().shape[0] < 2:
        return (f"Only {label(rows.iloc[0])} has records here: nothing to compare it with.",)
    said = []
    for split, part in sorted(rows.groupby("split"), key=lambda item: split_order(str(item[0]))):
        if len(part) >= 2:
            said.append(_compared(part.sort_values("rank", kind="stable"), robot, split, label))
    if score is not None:
        said += _closed_loop(rows, score, label)
    return tuple(said)


def _pair(part: pd.DataFrame) -> tuple[pd.Series, pd.Series]:
    """The best equivariant row and the best other one; the two lowest when a kind lacks."""
    kinds = [part[part.equivariant == claim] for claim in (True, False)]
    if all(len(kind) for kind in kinds):
        return kinds[0].iloc[0], kinds[1].iloc[0]
    return part.iloc[0], part.iloc[1]


def _compared(part: pd.DataFrame, robot: str, split: str, label: Label) -> str:
    """The ratio of the pair's errors over their common seeds (of geometric means) with the
    paired t-interval of the log ratio: the bands' test, so the interval excludes 1 exactly
    when the verdict tells them apart."""
    a, b = _pair(part)
    seeds_a, seeds_b = a.per_seed[RMSE], b.per_seed[RMSE]
    common = sorted(set(seeds_a) & set(seeds_b))
    ratios = [seeds_a[s] / seeds_b[s] for s in common]
    logs = t_interval(list(portable_math.log(ratios))) if common else None
    ratio = (
        metric_cell(math.exp(logs.value), math.exp(logs.low), math.exp(logs.high), 2)
        if logs is not None
        else metric_cell(np.nan, np.nan, np.nan, 2)
    )
    verdict = (
        "a paired t-test over seeds tells them apart"
        if differ(seeds_a, seeds_b)
        else "a paired t-test over seeds cannot tell them apart: a tie"
    )
    return (
        f"On {robot} {split}, {label(a)}'s test error is {ratio} {TIMES} {label(b)}'s "
        f"({cell_of(a, RMSE)} against {cell_of(b, RMSE)} N m); {verdict}."
    )


def _closed_loop(rows: pd.DataFrame, score: str, label: Label) -> list[str]:
    said = []
    measured = rows[rows[f"{score}_mean"].notna()].groupby("split")
    for split, part in sorted(measured, key=lambda item: split_order(str(item[0]))):
        ranked = part.sort_values(f"{score}_mean", ascending=False, kind="stable")
        top, bottom = ranked.iloc[0], ranked.iloc[-1]
        text = (
            f"Closed loop on {split}: the highest {score} is {label(top)}'s, {cell_of(top, score)}"
        )
        if len(ranked) > 1:
            text += f"; the lowest {label(bottom)}'s, {cell_of(bottom, score)}"
        said.append(text + " (0: the PD alone, 1: the oracle).")
    return said

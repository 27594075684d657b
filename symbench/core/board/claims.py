"""The paper's claims measured on a board (claims.md): each claim as comparisons between two
models, a ratio of their test errors or a difference of their closed-loop scores, over the
seeds both have, with a 95 % interval and the verdict that follows from the interval alone,
whichever way it falls: **holds** when it lies wholly on the side the paper predicts,
**fails** when it lies wholly on the other, a **tie** when it contains no difference (1 for
a ratio, 0 for a difference). A comparison whose models or splits the board lacks is left
out.

The interval is the paired Student-t interval of the per-seed log ratio (or difference): the
test that splits the rank bands (`statistics.differ`), so a claim and the bands never
disagree. A percentile bootstrap of 3 paired seeds would call two equal models different a
quarter of the time (docs/leaderboard-protocol.md#statistics). Ratios are ratios of
geometric means over seeds.

The paper names its architectures, so the pairs are fixed: SDNN against FFNN (the paper's
headline) and against `ffnn-leg` (the same leg-grouped input without the symmetry), SD-GNN
against GNN (the same message passing without it). Entries are the board's main ones: the
`acc` variant in the torch backend.
"""

from __future__ import annotations

import math
from collections.abc import Iterator, Mapping
from dataclasses import dataclass

import numpy as np
import pandas as pd

from symbench.core.board.sizes import default_size
from symbench.core.board.statistics import Interval, t_interval, welch_interval
from symbench.core.common import portable_math
from symbench.core.common.errors import SymbenchError
from symbench.core.robot.specs import load_robot

VARIANT, BACKEND = "acc", "torch"
PAIRS = (("ffnn", "sdnn"), ("ffnn-leg", "sdnn"), ("gnn", "sdgnn"))  # (plain, symmetric)
CLOSED_LOOP_PAIRS = (("sdgnn", "ffnn"), ("sdnn", "ffnn"))  # (symmetric, plain)
CLOSED_LOOP_SCORES = ("cl_tracking", "cl_score")  # the continuous score where records have it
SMALLEST_FRACTION = "fraction-0.1"  # the sample-efficiency claim's split
# the splits that hold orientations out of training (initial yaws; slope headings), each
# with its control: as many training climbs drawn from every orientation
HELD_OUT = (("unseen-rotation", "control-rotation"), ("unseen-heading", "control-heading"))

Seeds = Mapping[int, float]


@dataclass(frozen=True)
class Comparison:
    dataset: str
    what: str  # e.g. "ffnn / sdnn on unseen-rotation"
    estimate: Interval
    seeds: int
    neutral: float  # no difference: 1 for a ratio, 0 for a difference
    predicted_above: bool  # the side of `neutral` the paper predicts

    @property
    def verdict(self) -> str:
        low, high = self.estimate.low, self.estimate.high
        if math.isnan(low):
            return "no interval (one seed)"
        if low > self.neutral:
            return "holds" if self.predicted_above else "fails"
        if high < self.neutral:
            return "fails" if self.predicted_above else "holds"
        return "tie"


@dataclass(frozen=True)
class Claim:
    title: str
    measure: str  # what each comparison computes, in words
    comparisons: tuple[Comparison, ...]


class _Board:
    """One protocol's main entries: a metric's values by seed for (dataset, split, model)."""

    def __init__(self, table: pd.DataFrame):
        main = table[(table.variant == VARIANT) & (table.backend == BACKEND)]
        self.rows = {(r.dataset, r.split, r.model): r for _, r in main.iterrows()}
        self.datasets = sorted(main.dataset.unique())
        self.robots = dict(zip(main.dataset, main.robot))

    def seeds(self, dataset: str, split: str, model: str, metric: str) -> Seeds | None:
        row = self.rows.get((dataset, split, model))
        if row is None or metric not in row.per_seed:
            return None
        values = {s: v for s, v in row.per_seed[metric].items() if not np.isnan(v)}
        return values or None


def _paired(
    dataset: str, what: str, series: list[Seeds | None], signs: tuple[int, ...], ratio: bool
) -> list[Comparison]:
    """The comparison of `series` over their common seeds, when the board has them all: per
    seed the signed sum of the values (of their logs for a `ratio`), its t-interval."""
    present = [s for s in series if s is not None]
    if len(present) < len(series):
        return []
    common = sorted(set.intersection(*(set(s) for s in present)))
    if not common:
        return []
    values = np.array([[s[k] for k in common] for s in present])
    # each seed's signed sum row by row, not a matrix product: BLAS kernels, chosen per CPU,
    # may sum in another order
    terms = np.asarray(signs, dtype=float)[:, None] * (
        portable_math.log(values) if ratio else values
    )
    estimate = t_interval(terms.sum(axis=0))
    if ratio:
        return [Comparison(dataset, what, _exp(estimate), len(common), 1.0, True)]
    return [Comparison(dataset, what, estimate, len(common), 0.0, True)]


def _exp(x: Interval) -> Interval:
    return Interval(math.exp(x.value), math.exp(x.low), math.exp(x.high))


def _rmse(board: _Board, dataset: str, split: str, *models: str) -> list[Seeds | None]:
    return [board.seeds(dataset, split, m, "rmse_Nm") for m in models]


def _unseen_orientations(board: _Board) -> Iterator[Comparison]:
    for dataset in board.datasets:
        for held_out, control_split in HELD_OUT:
            for plain, symmetric in PAIRS:
                unseen = _rmse(board, dataset, held_out, plain, symmetric)
                yield from _paired(
                    dataset, f"{plain} / {symmetric} on {held_out}", unseen, (1, -1), True
                )
                # each model's penalty for the unseen orientations: its error over its own
                # size-matched control's
                control = _rmse(board, dataset, control_split, plain, symmetric)
                yield from _paired(
                    dataset,
                    f"{plain}'s penalty / {symmetric}'s ({held_out} / {control_split})",
                    [unseen[0], control[0], unseen[1], control[1]],
                    (1, -1, -1, 1),
                    True,
                )


def _less_data(board: _Board) -> Iterator[Comparison]:
    for dataset in board.datasets:
        for plain, symmetric in PAIRS:
            errors = _rmse(board, dataset, SMALLEST_FRACTION, plain, symmetric)
            what = f"{plain} / {symmetric} on {SMALLEST_FRACTION}"
            yield from _paired(dataset, what, errors, (1, -1), True)


def _closed_loop(board: _Board) -> Iterator[Comparison]:
    for dataset in board.datasets:
        for split in ("iid", "unseen-rotation"):
            for symmetric, plain in CLOSED_LOOP_PAIRS:
                for metric in CLOSED_LOOP_SCORES:
                    scores = [board.seeds(dataset, split, m, metric) for m in (symmetric, plain)]
                    what = f"{symmetric} - {plain} {metric} on {split}"
                    found = _paired(dataset, what, scores, (1, -1), False)
                    yield from found
                    if found:
                        break


def _legs(robot: str) -> int | None:
    try:
        return load_robot(robot).n_legs
    except SymbenchError:  # a robot this installation does not have: left out
        return None


def _more_legs(board: _Board) -> Iterator[Comparison]:
    """FFNN's normalized error on iid, a robot with more legs over one with fewer, between
    the datasets of one preset and version (their seeds do not pair up: Welch on logs)."""
    family = {d: d.removeprefix(f"{board.robots[d]}-") for d in board.datasets}
    legs = {d: _legs(board.robots[d]) for d in board.datasets}
    for fewer in board.datasets:
        for more in board.datasets:
            nf, nm = legs[fewer], legs[more]
            if family[fewer] != family[more] or nf is None or nm is None or nm <= nf:
                continue
            more_errors = board.seeds(more, "iid", "ffnn", "nrmse")
            fewer_errors = board.seeds(fewer, "iid", "ffnn", "nrmse")
            if more_errors is None or fewer_errors is None:
                continue
            estimate = welch_interval(
                list(portable_math.log(list(more_errors.values()))),
                list(portable_math.log(list(fewer_errors.values()))),
            )
            yield Comparison(
                f"{more} / {fewer}",
                f"ffnn nrmse on iid, {nm} legs over {nf}",
                _exp(estimate),
                min(len(more_errors), len(fewer_errors)),
                1.0,
                True,
            )


def claims(table: pd.DataFrame) -> list[Claim]:
    """The claims measured on one protocol's part of an aggregated board (those the board
    can test at all)."""
    board = _Board(table)
    ratio = "ratio of test RMSE (geometric means over seeds), plain model over symmetric one"
    found = [
        Claim(
            "SDNN and SD-GNN generalize to unseen rotations, the others do not",
            f"{ratio} (above 1: the symmetric model is better), on unseen yaws "
            "(unseen-rotation) and unseen slope headings (unseen-heading); a model's penalty "
            "is its error there over its error on the control split of the same training size",
            tuple(_unseen_orientations(board)),
        ),
        Claim(
            "Symmetric models need less data",
            f"{ratio} at 10 % of the training climbs ({SMALLEST_FRACTION})",
            tuple(_less_data(board)),
        ),
        Claim(
            "An SD-GNN controller keeps the robot on its path; FFNN falls",
            "difference of mean closed-loop score (0: the PD floor, 1: the oracle), symmetric "
            "model minus FFNN; cl_tracking where the board has it, else cl_score",
            tuple(_closed_loop(board)),
        ),
        Claim(
            "FFNN degrades as legs increase",
            "ratio of FFNN's normalized test RMSE on iid (geometric means), the robot with "
            "more legs over the one with fewer (above 1: it degrades); Welch's interval, "
            "as two datasets' seeds do not pair up",
            tuple(_more_legs(board)),
        ),
    ]
    return [c for c in found if c.comparisons]


def claims_markdown(table: pd.DataFrame) -> str:
    """claims.md: the claims once per training protocol, never mixing them, at the models'
    default sizes only (the paper compares its architectures as published)."""
    lines = [
        "# The paper's claims on this board",
        "",
        "Each row compares two models over the seeds both have: a ratio of test RMSE or a "
        "difference of closed-loop scores, with its 95 % paired t-interval (the test of the "
        "rank bands). The verdict follows from the interval alone: **holds** when it lies "
        "wholly on the side the paper predicts, **fails** when it lies wholly on the other "
        f"side, **tie** when it contains no difference. Entries: the `{VARIANT}` variant, "
        f"{BACKEND} backend, at the models' default sizes: runs matched to a parameter "
        "count (`--parameters`) are left out here; the robot pages and summary.md show them "
        "in their own sections.",
        "",
    ]
    for protocol, part in default_size(table).groupby("protocol", sort=True):
        lines += [f"# Trained under the {protocol} protocol", ""]
        for number, claim in enumerate(claims(part), 1):
            lines += [
                f"## {number}. {claim.title}",
                "",
                claim.measure[0].upper() + claim.measure[1:] + ".",
                "",
                "| dataset | comparison | estimate [95 % CI] | seeds | verdict |",
                "|---|---|---|---|---|",
            ]
            lines += [
                f"| {c.dataset} | {c.what} | {_estimate(c.estimate)} | {c.seeds} | "
                f"**{c.verdict}** |"
                for c in claim.comparisons
            ]
            lines.append("")
    return "\n".join(lines)


def _estimate(x: Interval) -> str:
    if math.isnan(x.low):
        return f"{x.value:.3g}"
    return f"{x.value:.3g} [{x.low:.3g}, {x.high:.3g}]"

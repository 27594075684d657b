"""The columns of the site's tables: what each holds in plain words, which direction is
better, and the order they are shown in (the headline first: the test torque RMSE, then the
closed-loop score, then the rest), so that every table and the glossary say the same."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np
import pandas as pd

from symbench.core.board.cells import grouped, metric_parts
from symbench.core.board.leaderboard import COLUMNS, MIN_SEEDS

CLOSED_LOOP = "closed-loop"
RMSE = COLUMNS[("torque-error", "rmse")]
# the closed loop's headline scores, the first present one shown: the continuous tracking
# score (dataset v7 on), else the score of the time held; both 0 = the PD alone, 1 = oracle
SCORES = (
    COLUMNS[(CLOSED_LOOP, "pd_tracking_score")],
    COLUMNS[(CLOSED_LOOP, "pd_normalized_score")],
)
HEADLINE = (RMSE, *SCORES)
BEST = "★"  # beside a mean in the best rank band of its split
OVER_SEEDS = "Mean [95 % bootstrap interval] over seeds."

# what each column holds, shown in the glossary and the header's tooltip
EXPLAINED = {
    "model": "The model; its link leads to every seed's record.",
    "rank": "Rank by mean test torque RMSE, as a band joining the models that a paired "
    "t-test over seeds cannot tell apart (1-2: tied for first).",
    "variant": "Input variant: acc (joint positions, velocities and accelerations: inverse "
    "dynamics) or next (positions and velocities now and one record period later).",
    "backend": "The framework that trained the model: torch or jax.",
    "rmse_Nm": "Test torque RMSE in N m: the error of the predicted joint torques on the "
    "split's test climbs.",
    "nrmse": "Test torque RMSE over the standard deviation of the test torques: comparable "
    "across robots.",
    "equiv_err": "Largest relative change of the prediction when the input is turned by "
    "the robot's symmetry group (0: exactly equivariant).",
    "invar_change": "Largest relative change of the prediction under the transformations "
    "it should ignore (0: exactly invariant).",
    "cl_success": "Closed loop: the share of reference climbs held to the end, with the "
    "model as feedforward and a weak joint PD.",
    "cl_held_s": "Closed loop: seconds each climb was held before a fall.",
    "cl_rmse_rad": "Closed loop: joint tracking RMSE in radians over the time held.",
    "cl_score": "Closed-loop score of the time held: 0 is the PD alone (the floor), 1 the "
    "expert's recorded feedforward replayed (the oracle).",
    "cl_tracking": "Closed-loop tracking score: the tracking cost placed between the PD "
    "alone (0, the floor) and the oracle (1), averaged over pushed reference climbs.",
    "data_tau_asym": "The dataset's own torque asymmetry under its symmetry group: the same "
    "for every model.",
    "parameters": "Trainable parameters.",
    "learning_rate": "The learning rate trained with (per robot where tuned on its own "
    "validation data: leaderboards/tuning).",
    "steps": "Gradient steps trained.",
    "epochs": "Passes over the training data.",
    "stopped_by": "Why training stopped, with the number of seeds.",
    "seeds": f"Seeds averaged (flagged below {MIN_SEEDS}).",
}
LOWER = {"rank", RMSE, "nrmse", "equiv_err", "invar_change", "cl_rmse_rad"}
HIGHER = {"cl_success", "cl_held_s", *SCORES}


@dataclass(frozen=True)
class Cell:
    text: str  # the mean (or the value) as shown
    value: str  # what sorting compares: the mean at full precision, "" when missing
    interval: str = ""  # '[low, high]' beside the mean, '' when there is none
    best: bool = False  # in the best rank band of its column
    link: str | None = None  # a page the cell leads to, relative to the site's root

    @property
    def shown(self) -> str:
        """The text with its interval, as one line: '0.0150 [0.0141, 0.0162]'."""
        return f"{self.text} {self.interval}" if self.interval else self.text


@dataclass(frozen=True)
class Column:
    name: str  # the leaderboard's column name (leaderboard.csv has the same)
    title: str  # what the column holds, in plain words
    numeric: bool
    read: Callable[[pd.Series], Cell] = field(compare=False, repr=False)
    label: str = ""  # the header, when it is not the name
    better: str = ""  # 'lower' or 'higher' is better; '' when neither is

    @property
    def header(self) -> str:
        return self.label or self.name


def mean_ci(name: str) -> Callable[[pd.Series], Cell]:
    """The mean [95 % interval] over seeds of an aggregated column."""

    def read(row: pd.Series) -> Cell:
        mean = float(row[f"{name}_mean"])
        shown, interval = metric_parts(mean, row[f"{name}_ci_low"], row[f"{name}_ci_high"])
        return Cell(shown, "" if np.isnan(mean) else repr(mean), interval)

    return read


def _seeds(row: pd.Series) -> Cell:
    flag = "" if row.seeds >= MIN_SEEDS else f" (<{MIN_SEEDS})"
    return Cell(f"{row.seeds}{flag}", str(row.seeds))


def _parameters(row: pd.Series) -> Cell:
    return Cell(grouped(row.parameters, 0), str(row.parameters))


def _learning_rate(row: pd.Series) -> Cell:
    return Cell(f"{row.learning_rate:g}", repr(float(row.learning_rate)))


def _text(name: str) -> Callable[[pd.Series], Cell]:
    def read(row: pd.Series) -> Cell:
        return Cell(str(row[name]), str(row[name]))

    return read


def _rank(row: pd.Series) -> Cell:
    return Cell(row.rank_band, str(row["rank"]))


def has(rows: pd.DataFrame, name: str) -> bool:
    return f"{name}_mean" in rows and bool(rows[f"{name}_mean"].notna().any())


def better(name: str) -> str:
    """Which direction of a metric is better: 'lower', 'higher' or ''."""
    return "lower" if name in LOWER else "higher" if name in HIGHER else ""


def metric(name: str) -> Column:
    explained = f"{EXPLAINED[name]} {OVER_SEEDS}"
    return Column(name, explained, True, mean_ci(name), better=better(name))


def board_columns(rows: pd.DataFrame) -> tuple[Column, ...]:
    """The columns with data among `rows`, the headline first: rank, test RMSE, the
    closed-loop scores, then how each row was made, the other metrics and the training."""
    headline = [metric(name) for name in HEADLINE if has(rows, name)]
    rest = [metric(n) for n in COLUMNS.values() if n not in HEADLINE and has(rows, n)]
    plain = [
        Column("variant", EXPLAINED["variant"], False, _text("variant")),
        Column("backend", EXPLAINED["backend"], False, _text("backend")),
    ]
    training = [
        Column("parameters", EXPLAINED["parameters"], True, _parameters),
        Column("learning_rate", EXPLAINED["learning_rate"], True, _learning_rate),
        *([metric("steps")] if has(rows, "steps") else []),
        metric("epochs"),
        Column("stopped_by", EXPLAINED["stopped_by"], False, _text("stopped_by")),
        Column("seeds", EXPLAINED["seeds"], True, _seeds),
    ]
    rank = Column("rank", EXPLAINED["rank"], True, _rank, better="lower")
    return (rank, *headline, *plain, *rest, *training)

"""Splits: trajectories (never samples) into train, validation and test.

A split is a registered `SplitEntry` whose `assign(context)` gives every trajectory one
label: "train", "val", "test" or "unused". The core checks the result (one label each,
non-empty train, val and test) and turns it into trajectory ids, so every model of a
comparison sees exactly the same samples for a given dataset and seed. Validation always
comes from the training side: `carve_validation` takes it out of the training trajectories.
The standard splits themselves are a plugin (`symbench.plugins.splits`); a generalization
split names its size-matched iid control (`SplitEntry.control`, read with `control_of`). A
column split
(`column_split("heading", ["0", "90"], ["180", "270"])`, named `heading_0_90_vs_180_270`)
is resolved here from its name, for any dataset whose scenarios hold that column.
"""

from __future__ import annotations

import re
import zlib
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from symbench.core.common.errors import SymbenchError, UnknownNameError
from symbench.core.sim.scene.scenario import DIRECTIONS

LABELS = ("train", "val", "test", "unused")
VAL_FRACTION = 0.15
_VERSION = re.compile(r"-v(\d+)$")


@dataclass(frozen=True)
class SplitContext:
    """What a split may look at: one scenario per trajectory, in trajectory-id order."""

    dataset_id: str
    trajectory_ids: np.ndarray  # (T,) ids as stored in ViewArrays.trajectory
    scenarios: tuple[dict[str, Any], ...]  # Scenario.to_dict() (fields may be None for imports)
    n_samples: np.ndarray  # (T,) samples each trajectory contributes to a view
    rotation_order: int  # pure rotations in the robot's group: sector width 360 / this
    seed: int

    @property
    def version(self) -> int | None:
        """The dataset version its id ends in (`hexa-climb-small-v6`: 6); None for an id
        without one (imported logs, tests' own ids)."""
        match = _VERSION.search(self.dataset_id)
        return int(match.group(1)) if match else None

    def rng(self, purpose: str) -> np.random.Generator:
        """A generator fixed by the seed and `purpose`, independent of call order."""
        return np.random.default_rng([self.seed, zlib.crc32(purpose.encode())])

    def values(self, field: str) -> np.ndarray:
        """One scenario field for every trajectory; an error if any trajectory lacks it."""
        vals = [s.get(field) for s in self.scenarios]
        if any(v is None for v in vals):
            raise SymbenchError(
                f"dataset {self.dataset_id}: some trajectories have no "
                f"'{field}', which this split needs"
            )
        return np.asarray(vals)


@dataclass(frozen=True)
class SplitIndices:
    """Trajectory ids of each part of one split of one dataset, for one seed."""

    split: str
    seed: int
    train: np.ndarray
    val: np.ndarray
    test: np.ndarray

    @property
    def sizes(self) -> dict[str, int]:
        """Trajectories (climbs) in each part: {"train": ..., "val": ..., "test": ...}."""
        return {k: len(getattr(self, k)) for k in ("train", "val", "test")}

    def to_dict(self) -> dict[str, Any]:
        return {
            "split": self.split,
            "seed": self.seed,
            **{k: getattr(self, k).tolist() for k in ("train", "val", "test")},
        }


def carve_validation(
    labels: np.ndarray, context: SplitContext, fraction: float = VAL_FRACTION
) -> np.ndarray:
    """Relabel a seeded `fraction` (at least one) of the "train" trajectories as "val"."""
    train = np.flatnonzero(labels == "train")
    if len(train) < 2:
        raise SymbenchError(
            f"dataset {context.dataset_id}: the training side has "
            f"{len(train)} trajectory, at least 2 are needed to carve a "
            "validation set by trajectory; use a larger preset"
        )
    n_val = min(len(train) - 1, max(1, round(fraction * len(train))))
    out = labels.copy()
    out[context.rng("validation").permutation(train)[:n_val]] = "val"
    return out


def resolve(split: str, context: SplitContext) -> SplitIndices:
    """Run the registered split `split` (or the column split it names, see `column_split`)
    and check what it returned."""
    from symbench.core.plugin import registry

    column = parse_column_split(split)
    if column is not None:
        return indices_from_labels(split, context, assign_column_split(column, context))
    entry = registry.split(split)
    try:
        labels = np.asarray(entry.assign(context), dtype=object)
    except SymbenchError:
        raise
    except Exception as exc:  # a plugin's bug: name it instead of a deep traceback
        raise SymbenchError(f"split '{split}' failed: {type(exc).__name__}: {exc}") from exc
    return indices_from_labels(split, context, labels)


def indices_from_labels(
    split: str, context: SplitContext, given: Sequence[str] | np.ndarray
) -> SplitIndices:
    labels = np.asarray(given, dtype=object)
    n = len(context.trajectory_ids)
    if labels.shape != (n,):
        raise SymbenchError(f"split '{split}' returned {labels.shape} labels for {n} trajectories")
    unknown = sorted(set(labels.tolist()) - set(LABELS))
    if unknown:
        raise SymbenchError(f"split '{split}' returned unknown label(s) {unknown}; use {LABELS}")
    parts = {k: np.sort(context.trajectory_ids[labels == k]) for k in ("train", "val", "test")}
    empty = [k for k, ids in parts.items() if len(ids) == 0]
    if empty:
        raise SymbenchError(
            f"split '{split}' of dataset {context.dataset_id} leaves {', '.join(empty)} empty"
        )
    return SplitIndices(split, context.seed, **parts)


# --- column splits: train and test chosen by the values of one scenario column ------------
# `heading_0_90_vs_180_270` trains on headings 0 and 90 and tests on 180 and 270: the name
# says the split and is a safe file name (it ends up in run keys). Values are joined by "_",
# a minus sign is written "m" (`yaw_m45_vs_45`).
COLUMNS = {  # the name on the command line: the scenario field
    "heading": "heading_deg",
    "yaw": "yaw_deg",
    "inclination": "inclination_deg",
    "direction": "direction",
    "seed": "seed",
}
ANGLES = ("heading_deg", "yaw_deg")  # compared modulo 360
MAX_TOKEN = 20  # characters of one value in a column split's name
_VALUE = re.compile(r"^(m?\d+(\.\d+)?|[a-z]+)$")


@dataclass(frozen=True)
class ColumnSplit:
    column: str  # a key of COLUMNS
    train: tuple[str, ...]
    test: tuple[str, ...]

    @property
    def name(self) -> str:
        return f"{self.column}_{'_'.join(self.train)}_vs_{'_'.join(self.test)}"

    @property
    def field(self) -> str:
        return COLUMNS[self.column]

    def describe(self) -> str:
        shown = (",".join(v.replace("m", "-") for v in side) for side in (self.train, self.test))
        return f"{self.column}: train on {next(shown)}, test on {next(shown)}"


def _token(value: str, column: str) -> str:
    """A value as the split's name writes it: a number in its shortest exact form (`:g`
    would write 1e+06, a name that does not parse back, and round to six digits), or a
    word."""
    text = value.strip()
    if column == "direction":
        if text not in DIRECTIONS:
            raise SymbenchError(f"direction '{text}' is not one of {', '.join(DIRECTIONS)}")
        return text
    try:
        number = float(text)
    except ValueError:
        raise SymbenchError(f"{column} value '{text}' is not a number") from None
    if not np.isfinite(number):
        raise SymbenchError(f"{column} value '{text}' is not finite")
    if column == "seed" and (number != int(number) or number < 0):
        raise SymbenchError(f"seed value '{text}' is not a whole number >= 0")
    # every digit, no exponent: the name parses back (`_VALUE`) to exactly this number
    token = np.format_float_positional(number + 0.0, trim="-").replace("-", "m")  # no -0
    if len(token) > MAX_TOKEN:
        raise SymbenchError(
            f"{column} value '{text}' takes {len(token)} characters written out; a split's "
            f"name, part of its records' file names, allows {MAX_TOKEN} per value"
        )
    return token


def column_split(column: str, train: Sequence[str], test: Sequence[str]) -> ColumnSplit:
    """The split training on the trajectories whose scenario `column` takes a `train` value
    and testing on those taking a `test` value; trajectories taking neither are unused. A
    value listed on both sides would put its trajectories in training and test at once, and
    is refused."""
    if column not in COLUMNS:
        raise UnknownNameError("split column", column, COLUMNS)
    sides = []
    for side, values in (("train", train), ("test", test)):
        tokens = tuple(dict.fromkeys(_token(str(v), column) for v in values))
        if not tokens:
            raise SymbenchError(f"--{side} gives no {column} value")
        sides.append(tokens)
    both = [v for v in sides[0] if _same(v, sides[1], column)]
    if both:
        raise SymbenchError(
            f"{column} {', '.join(v.replace('m', '-') for v in both)} is listed for both train "
            "and test: its trajectories would be trained and tested on (leakage)"
        )
    return ColumnSplit(column, sides[0], sides[1])


def _number(token: str) -> float:
    return float(token.replace("m", "-"))


def _same(token: str, tokens: Sequence[str], column: str) -> bool:
    return any(_matches(np.asarray([token], dtype=object), t, column)[0] for t in tokens)


def _matches(values: np.ndarray, token: str, column: str) -> np.ndarray:
    """Which of a trajectory column's `values` equal `token` (angles modulo 360)."""
    if column == "direction":
        return np.asarray([v == token for v in values])
    numbers = np.asarray([_number(v) if isinstance(v, str) else v for v in values], float)
    target = _number(token)
    if COLUMNS[column] in ANGLES:
        diff = np.mod(numbers - target + 180.0, 360.0) - 180.0
        return np.abs(diff) < 1e-6
    return np.abs(numbers - target) < 1e-9


def parse_column_split(name: str) -> ColumnSplit | None:
    """The column split a name describes (`heading_0_90_vs_180_270`), else None."""
    column, _, rest = name.partition("_")
    if column not in COLUMNS or name.count("_vs_") != 1:
        return None
    train, test = rest.split("_vs_")
    sides = [side.split("_") for side in (train, test)]
    if not all(side and all(_VALUE.match(v) for v in side) for side in sides):
        return None
    split = column_split(column, *[[v.replace("m", "-") for v in s] for s in sides])
    return split if split.name == name else None


def assign_column_split(split: ColumnSplit, context: SplitContext) -> np.ndarray:
    """Labels of a column split: train or test by the listed values, unused otherwise, then
    validation carved out of the training side."""
    values = context.values(split.field)
    present = sorted({str(v) for v in values.tolist()})
    labels = np.full(len(values), "unused", dtype=object)
    for side, tokens in (("train", split.train), ("test", split.test)):
        for token in tokens:
            hit = _matches(values, token, split.column)
            if not hit.any():
                raise SymbenchError(
                    f"dataset {context.dataset_id}: no trajectory has {split.column} "
                    f"{token.replace('m', '-')} (it has {', '.join(present)})"
                )
            labels[hit] = side
    return carve_validation(labels, context)


def control_of(split: str) -> str | None:
    """The size-matched iid control of a generalization split (`control-rotation` for
    `unseen-rotation`): the same numbers of training, validation and test climbs drawn at
    random from the same dataset with the same seed. The generalization gap of a model is its
    test error on `split` over its test error on the control, seed by seed. None for a split
    without one (`iid`, the fractions, the controls themselves, column splits); an error for
    an unknown name."""
    if parse_column_split(split) is not None:
        return None
    from symbench.core.plugin import registry

    return registry.split(split).control


def check_split(name: str) -> None:
    """A registered split or a column split's name, else an error naming the closest."""
    if parse_column_split(name) is None:
        from symbench.core.plugin import registry

        registry.split(name)

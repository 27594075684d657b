"""Splits: trajectories (never samples) into train, validation and test.

A split is a registered `SplitEntry` whose `assign(context)` gives every trajectory one
label: "train", "val", "test" or "unused". The core checks the result (one label each,
non-empty train, val and test) and turns it into trajectory ids, so every model of a
comparison sees exactly the same samples for a given dataset and seed. Validation always
comes from the training side: `carve_validation` takes it out of the training trajectories.
The standard splits themselves are a plugin (`symbench.plugins.splits`).
"""

from __future__ import annotations

import zlib
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from symbench.core.common.errors import SymbenchError

LABELS = ("train", "val", "test", "unused")
VAL_FRACTION = 0.15


@dataclass(frozen=True)
class SplitContext:
    """What a split may look at: one scenario per trajectory, in trajectory-id order."""

    dataset_id: str
    trajectory_ids: np.ndarray  # (T,) ids as stored in ViewArrays.trajectory
    scenarios: tuple[dict[str, Any], ...]  # Scenario.to_dict() (fields may be None for imports)
    n_samples: np.ndarray  # (T,) samples each trajectory contributes to a view
    rotation_order: int  # pure rotations in the robot's group: sector width 360 / this
    seed: int

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
    """Run the registered split `split` and check what it returned."""
    from symbench.core.plugin import registry

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

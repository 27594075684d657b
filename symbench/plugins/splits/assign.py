"""The standard splits' assignments: each labels every trajectory of a dataset.

They use only the public API (`symbench.SplitContext`, `symbench.carve_validation`), as a
third-party split would.

Two sets of rules. Datasets up to v6 are grids of scenarios (evenly spaced yaws, a few
headings) whose climbs are often exact rotated images of each other; their splits keep the
definitions their published records were made with (`grid_rules`). From v7 every climb's
start is drawn from continuous distributions and no climb is an image of another: there the
generalization splits hold out a region of the scenario space and test on a random subset of
it of iid's test size (`iid_test_size`), so that every generalization split and its
size-matched iid control (`control`) test on as many climbs and errors compare.
"""

from __future__ import annotations

import json
import math
from collections.abc import Callable
from typing import Any

import numpy as np

from symbench import SplitContext, SymbenchError, carve_validation

TEST_FRACTION = 0.2
LAST_GRID_VERSION = 6  # the last dataset version made of scenario grids


def iid_test_size(n: int) -> int:
    """iid's test climbs among `n`: 20 %, at least 1, leaving at least 2 to train on."""
    return min(n - 2, max(1, round(TEST_FRACTION * n)))


def grid_rules(context: SplitContext) -> bool:
    """Whether the grid (v6) definitions apply: a dataset up to v6, or one whose id has no
    version (imported logs) and whose climbs include exact rotated images of each other."""
    if context.version is not None:
        return context.version <= LAST_GRID_VERSION
    return len(set(_image_keys(context))) < len(context.scenarios)


def _image_keys(context: SplitContext) -> list[str]:
    """Per climb, its scenario with the initial yaw taken into the fundamental sector: two
    climbs share a key when one is a rotated image (or a copy) of the other. Every climb gets
    its own key when some climb has no yaw (nothing is known to be an image then)."""
    if any(s.get("yaw_deg") is None for s in context.scenarios):
        return [str(i) for i in range(len(context.scenarios))]
    _, offsets, _ = _sector_offsets(context)
    keys = []
    for scenario, offset in zip(context.scenarios, offsets.tolist(), strict=True):
        rest = {k: v for k, v in scenario.items() if k != "yaw_deg"}
        keys.append(json.dumps([offset, rest], sort_keys=True, default=str))
    return keys


def _sized_test(labels: np.ndarray, context: SplitContext, split: str) -> np.ndarray:
    """Keep a seeded random `iid_test_size` of the eligible test climbs (all of them when fewer
    are eligible); the others become unused."""
    eligible = np.flatnonzero(labels == "test")
    out = labels.copy()
    drop = context.rng(f"{split}-test").permutation(eligible)[iid_test_size(len(labels)) :]
    out[drop] = "unused"
    return out


def iid(context: SplitContext) -> np.ndarray:
    """Held-out trajectories from the same scenario distribution."""
    n = len(context.trajectory_ids)
    if n < 3:
        raise SymbenchError(
            f"dataset {context.dataset_id}: iid needs at least 3 trajectories, has {n}"
        )
    n_test = iid_test_size(n)
    labels = np.full(n, "train", dtype=object)
    labels[context.rng("iid-test").permutation(n)[:n_test]] = "test"
    return carve_validation(labels, context)


def unseen_heading(context: SplitContext) -> np.ndarray:
    """Grid rules: train on the lower half of the slope headings (sorted, mod 360), test on
    the rest. Continuous rules: train on the headings in [0, 180) degrees, test on a random
    `iid_test_size` of the climbs heading in [180, 360)."""
    if not grid_rules(context):
        headings = np.mod(context.values("heading_deg").astype(float), 360.0)
        lower = headings < 180.0
        if lower.all() or not lower.any():
            raise SymbenchError(
                f"dataset {context.dataset_id}: unseen-heading needs slope headings both in "
                f"[0, 180) and in [180, 360) degrees, all {int(lower.sum())} of "
                f"{len(lower)} climbs head into [0, 180)"
            )
        labels = np.where(lower, "train", "test").astype(object)
        return carve_validation(_sized_test(labels, context, "unseen-heading"), context)
    headings = np.round(np.mod(context.values("heading_deg").astype(float), 360.0), 6)
    unique = np.unique(headings)
    if len(unique) < 2:
        raise SymbenchError(
            f"dataset {context.dataset_id}: unseen-heading needs at least 2 "
            f"slope headings, found {unique.tolist()}"
        )
    seen = unique[: math.ceil(len(unique) / 2)]
    labels = np.where(np.isin(headings, seen), "train", "test").astype(object)
    return carve_validation(labels, context)


def _sector_offsets(context: SplitContext) -> tuple[float, np.ndarray, np.ndarray]:
    """(sector width, each yaw's offset within its sector, whether it is in the first)."""
    width = 360.0 / context.rotation_order
    yaws = np.mod(context.values("yaw_deg").astype(float), 360.0)
    offsets = np.round(np.mod(yaws, width), 6) % round(width, 6)
    return width, offsets, yaws < width - 1e-6


def orbit_rotation(context: SplitContext) -> np.ndarray:
    """Train on initial yaws in the fundamental sector [0, 360 / order), test on the others.

    A pure equivariance check: on an even yaw grid every test climb is an exact symmetric
    image of a training climb, so an equivariant model meets no new motion here. Under the
    continuous rules only the exact rotated images of training climbs test (the rest is
    unused), and a dataset without any (continuous draws, v7) is refused: there is nothing
    for this split to measure, `unseen-rotation` is its generalization counterpart."""
    width, _, inside = _sector_offsets(context)
    if inside.all() or not inside.any():
        raise SymbenchError(
            f"dataset {context.dataset_id}: orbit-rotation needs initial yaws "
            f"both inside and outside [0, {width:g}) degrees"
        )
    labels = np.where(inside, "train", "test").astype(object)
    if not grid_rules(context):
        keys = np.asarray(_image_keys(context), dtype=object)
        images = ~inside & np.isin(keys, keys[inside])
        if not images.any():
            raise SymbenchError(
                f"dataset {context.dataset_id}: orbit-rotation needs climbs that are exact "
                f"rotated images of climbs in [0, {width:g}) degrees (a yaw grid, datasets "
                "up to v6); this one has none (continuous draws): use unseen-rotation to "
                "test generalization to other rotations, and `symbench data symmetry "
                f"{context.dataset_id}` to measure the data's symmetry on pairs "
                "constructed on purpose"
            )
        labels[~inside & ~images] = "unused"
    return carve_validation(labels, context)


def unseen_rotation(context: SplitContext) -> np.ndarray:
    """Continuous rules (the design's definition): train on the climbs whose initial yaw lies
    in the fundamental sector [0, 360 / order), test on a random `iid_test_size` of the others
    that are not exact rotated images of a training climb (with continuous draws, all of
    them). A model without the symmetry must carry what it learned into sectors it never
    saw; an equivariant one meets new motions (every climb's other draws differ).

    Grid rules (datasets up to v6, whose yaws are an even grid): train on every other yaw of
    the fundamental sector; test, in the other sectors, on the yaws whose offset within their
    sector falls between the training yaws, so that no test climb is a symmetric image of a
    training climb. The rest (the first sector's other yaws, the other sectors' images of the
    training yaws) is unused."""
    if not grid_rules(context):
        return _unseen_sectors(context)
    width, offsets, inside = _sector_offsets(context)
    first = np.unique(offsets[inside])
    trained = first[::2]
    test = ~inside & ~np.isin(offsets, trained)
    if len(first) == 0 or not test.any():
        raise SymbenchError(
            f"dataset {context.dataset_id}: unseen-rotation needs initial yaws in "
            f"[0, {width:g}) degrees and, outside it, yaws between their rotated images"
        )
    labels = np.full(len(offsets), "unused", dtype=object)
    labels[inside & np.isin(offsets, trained)] = "train"
    labels[test] = "test"
    return carve_validation(labels, context)


def _unseen_sectors(context: SplitContext) -> np.ndarray:
    width, _, inside = _sector_offsets(context)
    keys = np.asarray(_image_keys(context), dtype=object)
    test = ~inside & ~np.isin(keys, keys[inside])
    if not inside.any() or not test.any():
        raise SymbenchError(
            f"dataset {context.dataset_id}: unseen-rotation needs climbs with initial yaws "
            f"in [0, {width:g}) degrees and, outside it, climbs that are not rotated images "
            f"of them ({int(inside.sum())} inside, {int(test.sum())} such outside)"
        )
    labels = np.where(inside, "train", "unused").astype(object)
    labels[test] = "test"
    return carve_validation(_sized_test(labels, context, "unseen-rotation"), context)


def unseen_inclination(context: SplitContext) -> np.ndarray:
    """Train on the gentler slopes, test on the steepest third of the dataset's inclinations
    (at least one): on the `transfer` grid, floor to wall trains, overhangs and the ceiling
    test. Every test slope lies beyond every training slope, so the model extrapolates."""
    inclinations = np.round(context.values("inclination_deg").astype(float), 6)
    unique = np.unique(inclinations)
    if len(unique) < 2:
        raise SymbenchError(
            f"dataset {context.dataset_id}: unseen-inclination needs at least 2 "
            f"inclinations, found {unique.tolist()}"
        )
    held_out = unique[len(unique) - math.ceil(len(unique) / 3) :]
    labels = np.where(np.isin(inclinations, held_out), "test", "train").astype(object)
    if not grid_rules(context):
        labels = _sized_test(labels, context, "unseen-inclination")
    return carve_validation(labels, context)


def unseen_gait(context: SplitContext) -> np.ndarray:
    """Train on the default leg order (the stepping sequence), test on every other one.

    No rotation of the robot turns one stepping sequence into the reversed one, so no test
    climb is a rotated image of a training climb; a mirror does reverse it, so a model
    equivariant to the robot's mirrors may meet mirrored images of its training climbs.
    Under the continuous rules the test climbs are a random `iid_test_size` of the others."""
    if any("leg_order" not in s for s in context.scenarios):
        raise SymbenchError(
            f"dataset {context.dataset_id}: some trajectories have no 'leg_order', "
            "which unseen-gait needs"
        )
    default = np.array([s["leg_order"] is None for s in context.scenarios])
    if default.all() or not default.any():
        raise SymbenchError(
            f"dataset {context.dataset_id}: unseen-gait needs climbs with the default leg "
            "order and climbs with another one"
        )
    labels = np.where(default, "train", "test").astype(object)
    if not grid_rules(context):
        labels = _sized_test(labels, context, "unseen-gait")
    return carve_validation(labels, context)


def fraction(share: float) -> Callable[[SplitContext], np.ndarray]:
    """The iid split with only a seeded `share` of its training trajectories kept.

    The kept sets are nested (0.1 within 0.25 within 0.5 ...), validation and test are the
    iid ones, so sample-efficiency curves differ only in the training data.
    """
    if not 0.0 < share <= 1.0:
        raise SymbenchError(f"a training fraction must be in (0, 1], got {share}")

    def assign(context: SplitContext) -> np.ndarray:
        labels = iid(context)
        train = context.rng("fraction-order").permutation(np.flatnonzero(labels == "train"))
        labels[train[max(1, math.ceil(share * len(train))) :]] = "unused"
        return labels

    assign.__doc__ = f"iid with {share:g} of the training trajectories"
    return assign


def control(split: Callable[[SplitContext], Any]) -> Callable[[SplitContext], np.ndarray]:
    """The size-matched iid control of `split`: as many test, training and validation climbs
    as `split` has on the same dataset and seed, drawn at random.

    The test climbs are the first of iid's own seeded order (iid's test set itself whenever
    the sizes agree, as they do for the generalization splits under the continuous rules);
    the training side is a seeded random draw from the remaining climbs (iid's training
    pool), its validation climbs a seeded random share of it. So a generalization split and
    its control differ in which climbs they hold out, not in how many: the ratio of their
    test errors (the generalization gap) is not a training-size effect."""

    def assign(context: SplitContext) -> np.ndarray:
        labels = np.asarray(split(context), dtype=object)
        n = len(labels)
        sizes = {part: int((labels == part).sum()) for part in ("train", "val", "test")}
        order = context.rng("iid-test").permutation(n)
        pool = context.rng("control-train").permutation(order[sizes["test"] :])
        out = np.full(n, "unused", dtype=object)
        out[order[: sizes["test"]]] = "test"
        out[pool[: sizes["train"]]] = "train"
        out[pool[sizes["train"] : sizes["train"] + sizes["val"]]] = "val"
        return out

    assign.__doc__ = f"size-matched iid control of {getattr(split, '__name__', 'a split')}"
    return assign

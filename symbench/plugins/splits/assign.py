"""The standard splits' assignments: each labels every trajectory of a dataset.

They use only the public API (`symbench.SplitContext`, `symbench.carve_validation`), as a
third-party split would.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np

from symbench import SplitContext, SymbenchError, carve_validation

TEST_FRACTION = 0.2


def iid(context: SplitContext) -> np.ndarray:
    """Held-out trajectories from the same scenario distribution."""
    n = len(context.trajectory_ids)
    if n < 3:
        raise SymbenchError(
            f"dataset {context.dataset_id}: iid needs at least 3 trajectories, has {n}"
        )
    n_test = min(n - 2, max(1, round(TEST_FRACTION * n)))
    labels = np.full(n, "train", dtype=object)
    labels[context.rng("iid-test").permutation(n)[:n_test]] = "test"
    return carve_validation(labels, context)


def unseen_heading(context: SplitContext) -> np.ndarray:
    """Train on the lower half of the slope headings (sorted, mod 360), test on the rest."""
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
    image of a training climb, so an equivariant model meets no new motion here."""
    width, _, inside = _sector_offsets(context)
    if inside.all() or not inside.any():
        raise SymbenchError(
            f"dataset {context.dataset_id}: orbit-rotation needs initial yaws "
            f"both inside and outside [0, {width:g}) degrees"
        )
    return carve_validation(np.where(inside, "train", "test").astype(object), context)


def unseen_rotation(context: SplitContext) -> np.ndarray:
    """Train on every other yaw of the fundamental sector; test, in the other sectors, on
    the yaws whose offset within their sector falls between the training yaws.

    No test climb is a symmetric image of a training climb, so an equivariant model must
    interpolate between yaws too, and a model without the symmetry must also carry what it
    learned into sectors it never saw. The rest (the first sector's other yaws, the other
    sectors' images of the training yaws) is unused."""
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
    return carve_validation(labels, context)


def unseen_gait(context: SplitContext) -> np.ndarray:
    """Train on the default leg order (the stepping sequence), test on every other one.

    No rotation of the robot turns one stepping sequence into the reversed one, so no test
    climb is a rotated image of a training climb; a mirror does reverse it, so a model
    equivariant to the robot's mirrors may meet mirrored images of its training climbs."""
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
    return carve_validation(np.where(default, "train", "test").astype(object), context)


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

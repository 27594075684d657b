"""A model's own symmetry group against its robot's: the leg permutations it is equivariant to.

A permutation relabels the legs in the model's own input: each leg's features move with the
leg and the shared (base) features stay, that is `x[:, src]` for the leg-grouped view and
the per-leg joint and flag columns relabelled for the vector and body-graph views; the model
is equivariant to it when f(sigma . x) == sigma . f(x) (float64, the kit's tolerance).
Inputs come from plausible raw states, so they are what the model sees. The permutations a
function is equivariant to form a group, so for up to 6 legs every one of the n!
permutations is tried; above that the robot group's elements, a transposition and an n-cycle
(together they generate all n! permutations) and a few random permutations. A model whose
group is larger than the robot's is over-constrained: it cannot tell apart legs that the
robot's geometry tells apart (when the per-leg constant features are equal for every leg,
as for hexa and nona, the data cannot tell them apart either).
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from symbench.core.data.symmetry import raw_action
from symbench.core.plugin.entries import ModelEntry
from symbench.core.symmetry.groups import LegGroup
from symbench.core.training.normalization import Normalizer
from symbench.testing.equivariance import (
    TOLERANCES,
    model_predictors,
    predict_stacked,
    relative_error,
    resolve_robot,
    view_of,
)
from symbench.testing.raw_states import synthetic_raw_states

EXHAUSTIVE_MAX_LEGS = 6


@dataclass(frozen=True)
class SymmetryGroupReport:
    model: str
    backend: str
    view: str
    group: str  # the robot's group
    n_legs: int
    robot_perms: tuple[tuple[int, ...], ...]
    tested: tuple[tuple[int, ...], ...]
    equivariant_to: tuple[tuple[int, ...], ...]  # the tested permutations that hold
    exhaustive: bool  # every one of the n! permutations tested
    full_symmetric: bool  # equivariant to a generating set of all n! permutations
    legs_alike: bool  # the per-leg constant features are equal for every leg

    @property
    def order(self) -> int:
        """Order of the measured group (n! when a generating set of all holds)."""
        return math.factorial(self.n_legs) if self.full_symmetric else len(self.equivariant_to)

    @property
    def contains_robot_group(self) -> bool:
        return set(self.robot_perms) <= set(self.equivariant_to)

    @property
    def description(self) -> str:
        n = self.n_legs
        if self.full_symmetric:
            return f"S{n}: all {math.factorial(n)} permutations"
        if set(self.equivariant_to) == set(self.robot_perms):
            return f"{self.group}: the robot's group"
        if len(self.equivariant_to) == 1:
            return "trivial: the identity only"
        held = "all" if self.exhaustive else f"{len(self.equivariant_to)} of {len(self.tested)}"
        return f"order {self.order} ({held} tested permutations hold)"

    @property
    def verdict(self) -> str:
        robot = f"robot group {self.group} (order {len(self.robot_perms)})"
        if not self.contains_robot_group:
            return f"{self.description}; breaks the {robot}"
        if self.order > len(self.robot_perms):
            return f"{self.description}; over-constrained: larger than the {robot}"
        return f"{self.description}; exactly the {robot}"

    def to_dict(self) -> dict[str, Any]:
        return {
            "model": self.model,
            "backend": self.backend,
            "view": self.view,
            "robot_group": self.group,
            "robot_group_order": len(self.robot_perms),
            "n_legs": self.n_legs,
            "measured_order": self.order,
            "measured_group": self.description,
            "contains_robot_group": self.contains_robot_group,
            "over_constrained": self.contains_robot_group and self.order > len(self.robot_perms),
            "exhaustive": self.exhaustive,
            "tested": len(self.tested),
            "legs_alike": self.legs_alike,
            "verdict": self.verdict,
            "equivariant_to": [list(p) for p in self.equivariant_to],
        }


def permutations_to_test(
    group: LegGroup, n_random: int = 16, seed: int = 0
) -> tuple[tuple[tuple[int, ...], ...], bool]:
    """(permutations, exhaustive): all n! up to `EXHAUSTIVE_MAX_LEGS` legs, else the group's
    elements, a transposition, an n-cycle and `n_random` random permutations."""
    n = group.n_legs
    if n <= EXHAUSTIVE_MAX_LEGS:
        return tuple(itertools.permutations(range(n))), True
    rng = np.random.default_rng([seed, 23])
    found = dict.fromkeys(g.perm for g in group if not g.reflect)
    found[tuple(range(n))] = None
    found[(1, 0, *range(2, n))] = None
    found[(*range(1, n), 0)] = None
    for _ in range(n_random):
        found[tuple(int(i) for i in rng.permutation(n))] = None
    return tuple(found), False


def measure_symmetry_group(
    entry: ModelEntry,
    group: LegGroup | str,
    n_samples: int = 4,
    seed: int = 0,
    hyper: dict[str, Any] | None = None,
    params: dict[str, np.ndarray] | None = None,
    normalizer: Normalizer | None = None,
    n_random: int = 16,
) -> SymmetryGroupReport:
    """The leg permutations `entry` (random or given parameters) is equivariant to, against
    the group of the robot (`group`: a registered robot's name, or a group)."""
    group, frames, source = resolve_robot(group)
    states = synthetic_raw_states(source, n_samples, seed)
    perms, exhaustive = permutations_to_test(group, n_random, seed)
    base = view_of(entry, states.raw, states)
    batches = [base]
    for perm in perms:
        src = np.argsort(perm)  # new leg perm[i] = old leg i
        if entry.view == "leg_grouped":
            batches.append({"x": base["x"][:, src]})
        else:
            batches.append(view_of(entry, raw_action.relabel_legs(states.raw, src), states))
    predict = model_predictors(entry, group.n_legs, seed, hyper, params, normalizer, ("float64",))
    y, *moved = predict_stacked(predict["float64"], batches)
    held = tuple(
        perm
        for perm, actual in zip(perms, moved, strict=True)
        if relative_error(actual, y[:, np.argsort(perm)]) <= TOLERANCES["float64"]
    )
    n = group.n_legs
    full = exhaustive and len(held) == math.factorial(n)
    full = full or {(1, 0, *range(2, n)), (*range(1, n), 0)} <= set(held)
    p = frames.base_origin_in_legs()
    return SymmetryGroupReport(
        entry.name,
        entry.backend,
        entry.view,
        group.name,
        n,
        tuple(g.perm for g in group if not g.reflect),
        perms,
        held,
        exhaustive,
        full,
        bool(np.allclose(p, p[0], atol=1e-9)),
    )

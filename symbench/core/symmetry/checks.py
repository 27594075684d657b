"""Exhaustive checks of the group axioms and of the action, usable for any robot's group.

Each check returns a list of violations (empty when it holds), so that a test can show both
that a real group passes and that a deliberately wrong one is caught.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from itertools import product
from typing import Any

import numpy as np

from symbench.core.symmetry.groups import GroupElement

Action = Callable[[GroupElement, Any, Any], Any]


def axiom_violations(elements: Sequence[GroupElement]) -> list[str]:
    """Closure, identity, inverses over all pairs, associativity over all triples."""
    found: list[str] = []
    members = set(elements)
    if len(members) != len(elements):
        found.append("an element is listed twice")
    n = elements[0].n_legs
    identity = GroupElement(tuple(range(n)))
    if identity not in members:
        found.append("no identity element")
    for a, b in product(elements, repeat=2):
        if a * b not in members:
            found.append(f"not closed: {a!r} * {b!r} = {a * b!r}")
    for a in elements:
        if a * identity != a or identity * a != a:
            found.append(f"identity law fails for {a!r}")
        if a.inverse() not in members or a * a.inverse() != identity:
            found.append(f"no inverse for {a!r}")
    for a, b, c in product(elements, repeat=3):
        if (a * b) * c != a * (b * c):
            found.append(f"not associative: {a!r}, {b!r}, {c!r}")
    return found


def homomorphism_violations(
    elements: Sequence[GroupElement],
    act: Action,
    x: np.ndarray,
    signs: np.ndarray,
    atol: float = 0.0,
) -> list[str]:
    """act(g, act(h, x)) == act(g * h, x) for every pair, and act(e, x) == x."""
    found: list[str] = []
    identity = GroupElement(tuple(range(elements[0].n_legs)))
    if not np.allclose(act(identity, x, signs), x, atol=atol, rtol=0):
        found.append("the identity does not act trivially")
    for g, h in product(elements, repeat=2):
        lhs = act(g, act(h, x, signs), signs)
        rhs = act(g * h, x, signs)
        if not np.allclose(lhs, rhs, atol=atol, rtol=0):
            found.append(f"act({g!r}, act({h!r}, x)) != act({g!r} * {h!r}, x)")
    return found

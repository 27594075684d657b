"""A plot's result in words, for its image's alt text: which entry is best and which worst,
at every x or group, so that a reader who cannot see the plot learns what it shows."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np

from symbench.core.board.plots import Series


def _at(x: Any) -> str:
    return f"{x:g}" if isinstance(x, float) else str(x)


def _extreme(series: Sequence[Series[Any]], xs: Sequence[Any], pick: Any) -> dict[Any, str]:
    """x -> the label `pick` (min or max) chooses by mean, among the series measured there."""
    chosen = {}
    for x in xs:
        means = {s.label: s.points[x].mean for s in series if x in s.points}
        means = {label: m for label, m in means.items() if not np.isnan(m)}
        if means:
            chosen[x] = pick(means, key=means.__getitem__)
    return chosen


def _listing(items: list[str]) -> str:
    """'a', 'a and b', 'a, b and c'."""
    return items[0] if len(items) == 1 else ", ".join(items[:-1]) + " and " + items[-1]


def _sentence(chosen: dict[Any, str], what: str, where: str) -> str:
    """'sdnn has the lowest error at every fraction.', else the entries and their x."""
    at: dict[str, list[str]] = {}
    for x, label in chosen.items():
        at.setdefault(label, []).append(_at(x))
    if len(chosen) > 1 and len(at) == 1:
        return f"{next(iter(at))} has the {what} at every {where}."
    entries = [
        f"{label} at {where}{'s' * (len(xs) > 1)} {_listing(xs)}" for label, xs in at.items()
    ]
    return f"The {what}: {'; '.join(entries)}."


def ranking(
    series: Sequence[Series[Any]],
    xs: Sequence[Any],
    where: str,
    best: str,
    worst: str,
    lower_is_better: bool,
) -> str:
    """'sdnn (acc, torch) has the lowest error at every fraction. ffnn (acc, torch) has the
    highest error at every fraction.', or which entry where they change places."""
    if len(series) == 1:
        return f"Only {series[0].label} is shown."
    low, high = _extreme(series, xs, min), _extreme(series, xs, max)
    first, last = (low, high) if lower_is_better else (high, low)
    return f"{_sentence(first, best, where)} {_sentence(last, worst, where)}"

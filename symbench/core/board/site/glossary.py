"""One line defining each split and each score a page shows, read from where they are
defined: the split registry's descriptions (`SplitEntry.description`, the plugin's own
words) and the columns' explanations, so that the site never restates them."""

from __future__ import annotations

from collections.abc import Iterable

from symbench.core.board.site.columns import EXPLAINED, HEADLINE
from symbench.core.board.summary import split_order
from symbench.core.plugin.registry import collect

UNREGISTERED = "no split of this name is registered in the installation that built the site"
Definitions = tuple[tuple[str, str], ...]  # (name, what it is) in the order shown


def splits(names: Iterable[str]) -> Definitions:
    """The splits among `names`, in the board's order, each with its registered description."""
    registered = collect("splits")
    return tuple(
        (name, getattr(registered.get(name), "description", "") or UNREGISTERED)
        for name in sorted(set(names), key=split_order)
    )


def scores(columns: Iterable[str]) -> Definitions:
    """The headline metrics among `columns` (test RMSE, closed-loop scores), explained."""
    shown = set(columns)
    return tuple((name, EXPLAINED[name]) for name in HEADLINE if name in shown)

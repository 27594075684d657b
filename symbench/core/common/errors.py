"""Errors that the command line shows as one clear message instead of a traceback."""

from __future__ import annotations

import difflib
from collections.abc import Iterable, Sequence
from typing import Any


class SymbenchError(Exception):
    """A user-facing error: the message names what is wrong and, where it can, the fix. It is
    one line, even where it quotes a name holding a line break (a key of a JSON file, say)."""

    def __str__(self) -> str:
        return " ".join(Exception.__str__(self).split())


class UnknownNameError(SymbenchError, KeyError):
    """A name (model, robot, split, ...) that no plugin registered."""

    def __init__(self, what: str, name: str, valid: Iterable[str]) -> None:
        self.what, self.name = what, name
        self.valid = sorted(set(valid))
        close = difflib.get_close_matches(name, self.valid, n=3, cutoff=0.5)
        hint = f"; did you mean {', '.join(close)}?" if close else ""
        known = ", ".join(self.valid) if self.valid else "none registered"
        super().__init__(f"unknown {what} '{name}'{hint} (known: {known})")


def first_of(names: Sequence[str], shown: int) -> str:
    """The first `shown` names and how many more: a message that names every one of a
    thousand would hide the line it is on."""
    more = f" and {len(names) - shown} more" if len(names) > shown else ""
    return ", ".join(names[:shown]) + more


def lookup(what: str, name: str, table: dict[str, Any]) -> Any:
    """Return table[name] or raise UnknownNameError listing the closest valid names."""
    try:
        return table[name]
    except KeyError:
        raise UnknownNameError(what, name, table) from None

"""The values of a parsed robot.toml, each read as the type its entry needs: a plugin author
writes the file by hand, so a table that is a number, a count that is text or a number that
is `true` is refused naming the entry, never converted (`float(True)` is 1) nor left to fail
deep inside the parser as an internal error."""

from __future__ import annotations

import math
from typing import Any

from symbench.core.common.errors import SymbenchError


def shown(value: Any) -> str:
    """`value` as a message shows it: its repr, cut to 40 characters."""
    text = repr(value)
    return text if len(text) <= 40 else text[:37] + "..."


def get(table: Any, key: str, where: str) -> Any:
    """Entry `key` of `table` (a table, or refused)."""
    if not isinstance(table, dict):
        raise SymbenchError(f"{where}: expected a table, got {shown(table)}")
    if key not in table:
        raise SymbenchError(f"{where}: missing '{key}'")
    return table[key]


def table(raw: Any, key: str, where: str) -> dict[str, Any]:
    """Entry `key` of `raw` that is itself a table."""
    value = get(raw, key, where)
    if not isinstance(value, dict):
        raise SymbenchError(f"{where}: [{key}] must be a table, got {shown(value)}")
    return value


def number(value: Any, where: str) -> float:
    """A finite number (an integer or a float; not a boolean, not text)."""
    if isinstance(value, bool) or not isinstance(value, int | float):
        raise SymbenchError(f"{where}: expected a number, got {shown(value)}")
    try:
        x = float(value)
    except OverflowError:  # an integer beyond any float
        raise SymbenchError(f"{where}: expected a finite number, got {shown(value)}") from None
    if not math.isfinite(x):
        raise SymbenchError(f"{where}: expected a finite number, got {shown(value)}")
    return x


def count(value: Any, where: str) -> int:
    """An integer (not a boolean)."""
    if isinstance(value, bool) or not isinstance(value, int):
        raise SymbenchError(f"{where}: expected an integer, got {shown(value)}")
    return value


def text(value: Any, where: str) -> str:
    if not isinstance(value, str):
        raise SymbenchError(f"{where}: expected text, got {shown(value)}")
    return value


def floats(value: Any, n: int, where: str) -> tuple[float, ...]:
    """`n` finite numbers."""
    if not isinstance(value, list) or len(value) != n:
        raise SymbenchError(f"{where}: expected {n} finite numbers, got {shown(value)}")
    try:
        return tuple(number(x, where) for x in value)
    except SymbenchError:
        raise SymbenchError(f"{where}: expected {n} finite numbers, got {shown(value)}") from None


def positive(value: Any, where: str) -> float:
    x = number(value, where)
    if x <= 0:
        raise SymbenchError(f"{where}: expected a positive number, got {shown(value)}")
    return x


def non_negative(value: Any, where: str) -> float:
    """Damping and stiffness: zero is allowed, a negative value would inject energy."""
    x = number(value, where)
    if x < 0:
        raise SymbenchError(f"{where}: expected a non-negative number, got {shown(value)}")
    return x


def positive_floats(value: Any, n: int, where: str) -> tuple[float, ...]:
    """Masses and principal inertias: MuJoCo needs them strictly positive."""
    out = floats(value, n, where)
    if min(out) <= 0:
        raise SymbenchError(f"{where}: expected {n} positive numbers, got {shown(value)}")
    return out


def limits(lower: Any, upper: Any, where: str) -> tuple[tuple[float, ...], tuple[float, ...]]:
    lo, hi = floats(lower, 3, f"{where} lower"), floats(upper, 3, f"{where} upper")
    if any(a >= b for a, b in zip(lo, hi, strict=True)):
        raise SymbenchError(f"{where}: every lower limit must be below its upper limit")
    return lo, hi


def positives(raw: dict[str, Any], keys: tuple[str, ...], where: str) -> list[float]:
    return [positive(get(raw, k, where), f"{where} {k}") for k in keys]

"""Reading JSON that symbench did not necessarily write: only plain, finite JSON, and any
other input (invalid UTF-8, NaN or Infinity, nesting deep enough to exhaust the recursion
limit, a number of thousands of digits) is one clear error, never a traceback."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

from symbench.core.common.errors import SymbenchError


def _refuse_constant(name: str) -> Any:
    raise ValueError(f"{name} is not a JSON number")


def loads(data: str | bytes) -> Any:
    """`json.loads`, raising ValueError for everything that is not plain, finite JSON."""
    try:
        return json.loads(data, parse_constant=_refuse_constant)
    except RecursionError:
        raise ValueError("nested too deeply") from None


def one_line(exc: BaseException) -> str:
    return " ".join(str(exc).split())


def parse_json(data: str | bytes, source: str) -> Any:
    """The JSON value of `data`; `source` names it in the error."""
    try:
        return loads(data)
    except ValueError as exc:  # JSONDecodeError, UnicodeDecodeError, digit limit, constants
        raise SymbenchError(f"{source}: not valid JSON ({one_line(exc)})") from None


def read_json(path: Path, what: str) -> Any:
    """The JSON value of the file at `path`; `what` says what the file is meant to be."""
    try:
        data = Path(path).read_bytes()
    except FileNotFoundError:
        raise SymbenchError(f"{what}: {path} does not exist") from None
    except OSError as exc:
        raise SymbenchError(f"{what}: {path} cannot be read ({exc.strerror or exc})") from None
    return parse_json(data, f"{what}: {path}")

"""A parsed TOML document written back as TOML (tomllib only reads), every table inline: how
the tests write robot.toml files edited value by value."""

from __future__ import annotations

import json
import math
import re
from typing import Any

BARE_KEY = re.compile(r"[A-Za-z0-9_-]+")


def toml_text(doc: Any) -> str:
    """`doc` (a table) as a TOML document; another value as the document `value = ...`."""
    if not isinstance(doc, dict):
        return f"value = {toml_value(doc)}\n"
    return "".join(f"{toml_key(k)} = {toml_value(v)}\n" for k, v in doc.items())


def toml_value(value: Any) -> str:
    """`value` as TOML (inline tables for tables); None, which TOML lacks, as an empty
    string."""
    if isinstance(value, dict):
        return "{" + ", ".join(f"{toml_key(k)} = {toml_value(v)}" for k, v in value.items()) + "}"
    if isinstance(value, list):
        return "[" + ", ".join(toml_value(v) for v in value) + "]"
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float) and not math.isfinite(value):
        return "nan" if math.isnan(value) else ("inf" if value > 0 else "-inf")
    if isinstance(value, int | float):
        return repr(value)
    return json.dumps("" if value is None else value)


def toml_key(key: str) -> str:
    return key if BARE_KEY.fullmatch(key) else json.dumps(key)

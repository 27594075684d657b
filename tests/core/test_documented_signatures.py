"""Every public function is documented with its arguments: docs/writing-plugins.md shows
`name(arg, ...)` naming each of its parameters (plugin-facing ones; `host` is internal)."""

from __future__ import annotations

import inspect
import re
from pathlib import Path

import symbench

WRITING_PLUGINS = Path(__file__).resolve().parents[2] / "docs" / "writing-plugins.md"
INTERNAL = {"host"}  # parameters tests use to pass their own plugin host


def undocumented_arguments(text: str) -> dict[str, list[str]]:
    """Public functions whose documented call leaves out parameters (all, when none is shown)."""
    missing = {}
    for name in symbench.__all__:
        function = getattr(symbench, name)
        if not inspect.isfunction(function):
            continue
        params = [p for p in inspect.signature(function).parameters if p not in INTERNAL]
        shown = re.findall(rf"`{re.escape(name)}\(([^`]*)\)`", text)
        named = {re.split(r"[=:]", a)[0].strip() for s in shown for a in s.split(",")}
        left_out = [p for p in params if p not in named]
        if left_out:
            missing[name] = left_out
    return missing


def test_every_public_function_shows_its_arguments():
    assert undocumented_arguments(WRITING_PLUGINS.read_text()) == {}


def test_the_check_catches_a_left_out_argument():
    text = WRITING_PLUGINS.read_text().replace("`load_robot(name)`", "`load_robot()`")
    assert undocumented_arguments(text) == {"load_robot": ["name"]}

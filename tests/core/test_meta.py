"""Every hook has a test and a section in CONTRIBUTING.md; the check itself can fail."""

from __future__ import annotations

import inspect
from pathlib import Path

from symbench.core.plugin import hookspecs

ROOT = Path(__file__).resolve().parents[2]


def hook_names() -> list[str]:
    return [
        n for n, f in inspect.getmembers(hookspecs, inspect.isfunction) if n.startswith("symbench_")
    ]


def missing_from(names: list[str], texts: list[str]) -> list[str]:
    return [n for n in names if not any(n in t for t in texts)]


def texts_of_tests() -> list[str]:
    own = Path(__file__).resolve()
    return [p.read_text() for p in (ROOT / "tests").rglob("test_*.py") if p.resolve() != own]


def test_there_are_hooks():
    assert set(hook_names()) >= {
        "symbench_models",
        "symbench_robots",
        "symbench_evaluators",
        "symbench_splits",
        "symbench_commands",
    }


def test_every_hook_is_documented():
    contributing = (ROOT / "CONTRIBUTING.md").read_text()
    assert missing_from(hook_names(), [contributing]) == []


def test_every_hook_has_a_test():
    assert missing_from(hook_names(), texts_of_tests()) == []


def test_the_meta_check_catches_a_new_hook():
    contributing = (ROOT / "CONTRIBUTING.md").read_text()
    fake = ["symbench_teleport_robot"]
    assert missing_from(hook_names() + fake, [contributing]) == fake
    assert missing_from(hook_names() + fake, texts_of_tests()) == fake

"""pytest imports test files by their base name (the folders are not packages), so two test
files of one name in two folders stop the whole suite at collection ("import file
mismatch"), as two merges of this project did. Every test file's name is its own."""

from __future__ import annotations

from collections import Counter
from collections.abc import Iterable
from pathlib import Path

TESTS = Path(__file__).resolve().parents[1]


def shared_names(paths: Iterable[Path]) -> list[str]:
    counts = Counter(p.name for p in paths)
    return sorted(name for name, n in counts.items() if n > 1)


def test_no_two_test_files_share_a_name():
    assert shared_names(TESTS.rglob("test_*.py")) == []


def test_the_name_check_can_fail():
    paths = [Path("a/test_x.py"), Path("b/test_x.py"), Path("b/test_y.py")]
    assert shared_names(paths) == ["test_x.py"]

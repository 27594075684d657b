"""The site's templates and static files ship in the wheel: pyproject.toml lists the package
and package-data patterns that cover every one of them (tests/packaging builds the wheel
and checks the modules; this checks the data files, which no module import would miss
until a site is built from an installed symbench)."""

from __future__ import annotations

import tomllib
from fnmatch import fnmatch
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
PACKAGE = "symbench.core.board.site"
FOLDER = ROOT / "symbench" / "core" / "board" / "site"


def uncovered(files: list[str], patterns: list[str]) -> list[str]:
    return [f for f in files if not any(fnmatch(f, pattern) for pattern in patterns)]


def test_every_template_and_static_file_is_package_data():
    setuptools = tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["setuptools"]
    assert PACKAGE in setuptools["packages"]
    data = sorted(
        p.relative_to(FOLDER).as_posix()
        for folder in ("templates", "static")
        for p in (FOLDER / folder).rglob("*")
        if p.is_file()
    )
    assert len(data) >= 7
    assert uncovered(data, setuptools["package-data"][PACKAGE]) == []


def test_the_coverage_check_can_fail():
    assert uncovered(["static/logo.svg", "static/site.js"], ["static/*.js"]) == ["static/logo.svg"]

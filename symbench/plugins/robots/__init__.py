"""Built-in robots: one `RobotEntry` per folder of the top-level robots/ (robot.toml, README.md).

The specs are package data: the build maps the repository's robots/ folder into the wheel as
`symbench/plugins/robots/specs/` (see [tool.setuptools] in pyproject.toml), read here with
`importlib.resources`. A source checkout or an editable install has no specs/ folder (setuptools'
editable finder cannot map a data-only subpackage), and reads robots/ in place, so an edited spec
counts at once.

A third-party package adds a robot the same way: implement `symbench_robots` and return a
`RobotEntry` pointing at a folder with robot.toml (and README.md).
"""

from __future__ import annotations

import os
import tomllib
from importlib.resources import files
from pathlib import Path

from symbench import RobotEntry, hookimpl


def _robots_dir() -> Path:
    installed = files(__name__) / "specs"
    if installed.is_dir():
        # A RobotEntry needs a real folder: true of every installed wheel (pip unpacks it),
        # not of a zip import, which symbench does not support.
        if not isinstance(installed, os.PathLike):
            raise RuntimeError(f"symbench's robot specs are not on the file system: {installed}")
        return Path(installed)
    checkout = Path(__file__).resolve().parents[3]
    if (checkout / "pyproject.toml").is_file() and (checkout / "robots").is_dir():
        return checkout / "robots"  # a source checkout or an editable install
    raise RuntimeError(
        f"symbench's built-in robot specs are missing: no {installed} (an installed wheel) and "
        f"no robots/ beside pyproject.toml in {checkout} (a source checkout); reinstall symbench"
    )


ROBOTS_DIR = _robots_dir()


@hookimpl
def symbench_robots() -> list[RobotEntry]:
    entries = []
    for spec in sorted(ROBOTS_DIR.glob("*/robot.toml")):
        with spec.open("rb") as f:
            description = str(tomllib.load(f).get("description", ""))
        entries.append(RobotEntry(spec.parent.name, spec.parent, description))
    return entries

"""Built-in robots: one `RobotEntry` per folder of robots/ at the repository root.

A third-party package adds a robot the same way: implement `symbench_robots` and return a
`RobotEntry` pointing at a folder with robot.toml (and README.md).
"""

from __future__ import annotations

import tomllib
from pathlib import Path

from symbench import RobotEntry, hookimpl

ROBOTS_DIR = Path(__file__).resolve().parents[3] / "robots"


@hookimpl
def symbench_robots() -> list[RobotEntry]:
    entries = []
    for spec in sorted(ROBOTS_DIR.glob("*/robot.toml")):
        with spec.open("rb") as f:
            description = str(tomllib.load(f).get("description", ""))
        entries.append(RobotEntry(spec.parent.name, spec.parent, description))
    return entries

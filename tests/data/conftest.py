"""Helpers for the data tests (the stand-in datasets are fixtures of tests/conftest.py)."""

from __future__ import annotations

import dataclasses

from symbench.core.data.presets import preset
from symbench.core.robot.specs import load_robot


def short_grid(robot: str, name: str = "small", seconds: float = 0.1):
    """A preset's scenarios, shortened so that the stand-in makes them in milliseconds."""
    spec = load_robot(robot)

    grid = preset(name).scenarios(robot, spec.n_legs, spec.group.rotation_order)
    return [dataclasses.replace(s, seconds=seconds) for s in grid]

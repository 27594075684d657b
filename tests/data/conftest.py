"""Fixtures: a private $SYMBENCH_HOME per test and datasets made by the stand-in simulator."""

from __future__ import annotations

import dataclasses

import pytest
from synthetic_raw import fake_simulate

from symbench.core.data.generation import generate
from symbench.core.data.presets import preset
from symbench.core.robots import load_robot


@pytest.fixture
def home(tmp_path, monkeypatch):
    monkeypatch.setenv("SYMBENCH_HOME", str(tmp_path / "home"))
    return tmp_path / "home"


@pytest.fixture
def smoke_hexa(home):
    """hexa's smoke grid, simulated by the stand-in: the same files layout as the real one."""
    return generate("hexa", "smoke", simulator=fake_simulate, show_progress=False)


def short_grid(robot: str, name: str = "small", seconds: float = 0.1):
    """A preset's scenarios, shortened so that the stand-in makes them in milliseconds."""
    spec = load_robot(robot)

    grid = preset(name).scenarios(robot, spec.n_legs, spec.group.rotation_order)
    return [dataclasses.replace(s, seconds=seconds) for s in grid]

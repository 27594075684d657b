"""Ten-second climbs on every robot and slope, and the ten-second symmetry (slow)."""

from __future__ import annotations

import math

import pytest

from symbench.core.robot.specs import load_robot
from symbench.core.sim.check import check
from symbench.core.sim.gait.plan import SETTLE
from symbench.core.sim.scene.arena import Arena
from symbench.core.sim.scene.scenario import Scenario
from symbench.core.sim.scene.setup import Climb
from symbench.core.sim.symmetry import check_generators

pytestmark = pytest.mark.slow


@pytest.mark.parametrize("heading,yaw", [(0.0, 0.0), (90.0, 20.0), (200.0, 45.0)])
@pytest.mark.parametrize("inclination", [0.0, 30.0, 60.0, 90.0])
@pytest.mark.parametrize("robot", ["magneto", "hexa", "nona"])
def test_ten_second_climb(robot, inclination, heading, yaw):
    report = check(Scenario(robot, inclination, heading, yaw, seconds=10.0))
    assert report.attached, report.failure
    m = report.metrics
    spec = load_robot(robot)
    slots = math.floor((10.0 - SETTLE) / spec.gait.step_duration)
    planned = slots * spec.gait.step_length / spec.n_legs
    assert m["distance_walked"] > 0.9 * planned
    assert report.torque_within_limit
    assert m["base_error_max"] < 0.01
    assert m["clipped_fraction"] < 0.02


def test_hexa_symmetry_over_ten_seconds():
    """The rotation and the mirror twins of a ten-second climb on a tilted, turned slope."""
    climb = Climb(load_robot("hexa"), Arena(60.0, 30.0), yaw_deg=10.0, seed=1)
    checks = check_generators(climb, 10.0)
    assert [c.generator for c in checks] == ["shift 1", "mirror 0"]
    for twin in checks:
        assert twin.ok and twin.columns["q"] < 1e-6, twin


@pytest.mark.parametrize("robot", ["magneto", "nona"])
def test_symmetry_of_the_other_robots_over_one_second(robot):
    climb = Climb(load_robot(robot), Arena(90.0, 0.0), yaw_deg=5.0, seed=2)
    for twin in check_generators(climb, 1.0):
        assert twin.error < 1e-8, twin

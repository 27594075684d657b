"""Scenarios whose yaws differ by symmetry steps are exact symmetric images of each other.

This is what makes `unseen-rotation` a test of equivariance: the test trajectories are the
training ones with the base turned and the legs relabelled, not new motions.
"""

from __future__ import annotations

import numpy as np
import pytest

from symbench.core.robot.specs import load_robot
from symbench.core.sim.climb.rollout import simulate
from symbench.core.sim.scene.scenario import Scenario
from symbench.core.sim.scene.setup import Climb


@pytest.mark.parametrize(
    "robot,yaw,direction",
    [("hexa", 120.0, "forward"), ("magneto", 180.0, "left"), ("nona", 40.0, "forward")],
)
def test_turned_scenario_reproduces_the_relabelled_run(robot, yaw, direction):
    spec = load_robot(robot)
    base = simulate(
        Scenario(robot=robot, inclination_deg=90.0, yaw_deg=7.0, direction=direction, seconds=0.5)
    )
    turned = simulate(
        Scenario(
            robot=robot, inclination_deg=90.0, yaw_deg=7.0 + yaw, direction=direction, seconds=0.5
        )
    )
    assert base.attached and turned.attached
    k = round(yaw / spec.symmetry_angle_deg) * spec.symmetry_shift
    source = (np.arange(spec.n_legs) + k) % spec.n_legs  # turned leg j is base leg j + k
    for column in ("q", "qd", "tau", "contact", "magnet"):
        np.testing.assert_allclose(
            turned.arrays[column], base.arrays[column][:, source], rtol=0, atol=1e-6, err_msg=column
        )


def test_within_the_first_step_the_direction_is_the_body_frames():
    spec = load_robot("hexa")
    climb = Climb.from_scenario(Scenario(robot="hexa", yaw_deg=30.0, direction="left"), spec)
    assert climb.direction_deg == 90.0 and climb.leg_order == tuple(range(6))
    turned = Climb.from_scenario(Scenario(robot="hexa", yaw_deg=90.0, direction="left"), spec)
    assert turned.yaw_deg == 90.0 and turned.direction_deg == pytest.approx(30.0)
    assert turned.leg_order == (5, 0, 1, 2, 3, 4)


def test_turned_scenario_is_the_group_action_on_the_raw_states():
    """All raw columns, base pose and world-frame vectors included, equal g . raw of the
    original for the rotation g that relabels by the symmetry step."""
    from symbench.core.data.symmetry.raw_action import act_on_raw
    from symbench.core.data.views.frames import LegFrames
    from symbench.core.symmetry.groups import shift

    spec = load_robot("hexa")
    base = simulate(
        Scenario(robot="hexa", inclination_deg=60.0, heading_deg=30.0, yaw_deg=10.0, seconds=0.5)
    )
    turned = simulate(
        Scenario(robot="hexa", inclination_deg=60.0, heading_deg=30.0, yaw_deg=70.0, seconds=0.5)
    )
    frames = LegFrames.from_spec(spec)
    errors = {}
    for k in range(6):
        moved = act_on_raw(shift(6, k), base.arrays, frames)
        errors[k] = max(float(np.abs(moved[c] - turned.arrays[c]).max()) for c in moved)
    best = min(errors, key=errors.get)
    assert errors[best] < 1e-6, errors
    assert sorted(errors.values())[1] > 1e-2  # and no other relabelling fits

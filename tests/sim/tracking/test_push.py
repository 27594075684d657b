"""The closed loop's push: applied at its steps, reproducible, the same for the expert and
for whoever tracks the pushed climb, and drawn from the scenario alone."""

from __future__ import annotations

import numpy as np
import pytest

from symbench.core.robot.specs import load_robot
from symbench.core.sim.climb.rollout import simulate
from symbench.core.sim.scene.push import Push
from symbench.core.sim.scene.scenario import Scenario
from symbench.core.sim.tracking.learned_control import track
from symbench.core.sim.tracking.references import oracle_policy, reference_push

SCENARIO = Scenario(robot="hexa", inclination_deg=90.0, seconds=1.0)
PUSH = Push(0.4, 0.1, (60.0, 40.0, 0.0))
STEPS = range(400, 500)  # PUSH's physics steps at 1 ms


@pytest.fixture(scope="module")
def pushed():
    return simulate(SCENARIO, record_period=0.001, push=PUSH)


def test_the_push_acts_on_its_steps_only(pushed):
    plain = simulate(SCENARIO, record_period=0.001)
    assert pushed.attached and plain.attached
    assert list(PUSH.steps(0.001)) == list(STEPS)
    # row k: the state before step k, and the torque step k applied (its damping taken at
    # the end of the step, which the push changes)
    for column, rows in (("q", STEPS.start + 1), ("base_pos", STEPS.start + 1), ("tau", 400)):
        np.testing.assert_array_equal(pushed.arrays[column][:rows], plain.arrays[column][:rows])
        assert not np.array_equal(pushed.arrays[column][rows], plain.arrays[column][rows])
    # the push moved the base: the expert's climb differs after it
    moved = np.abs(pushed.arrays["base_pos"][STEPS.stop] - plain.arrays["base_pos"][STEPS.stop])
    assert moved.max() > 1e-3


def test_the_push_is_reproducible(pushed):
    again = simulate(SCENARIO, record_period=0.001, push=PUSH)
    for column, values in pushed.arrays.items():
        np.testing.assert_array_equal(again.arrays[column], values)


def test_the_pushed_climb_replays_only_when_pushed_alike(pushed):
    """The oracle of a pushed reference, pushed at the same steps, is the expert's climb to
    rounding; unpushed, the same torques leave it."""
    control = load_robot("hexa").control
    gains = (0.1 * control.kp, 0.1 * control.kd)
    policy = oracle_policy(pushed.arrays)
    replay = track(SCENARIO, pushed.arrays, policy, gains, push=PUSH)
    assert replay.attached and replay.max_joint_error_rad < 1e-9
    assert replay.tracking_cost < 1e-9
    unpushed = track(SCENARIO, pushed.arrays, policy, gains)
    assert unpushed.max_joint_error_rad > 1e-3


def test_the_force_lies_in_the_surface_plane_as_drawn():
    wall = np.array([1.0, 0.0, 0.0])  # a wall: downhill is world -z
    np.testing.assert_allclose(Push(0, 0.1, (10.0, 0, 0)).world_force(wall), [0, 0, -10.0])
    across = Push(0, 0.1, (0, 10.0, 0)).world_force(wall)
    assert abs(across @ wall) < 1e-12 and abs(across[2]) < 1e-12 and np.linalg.norm(across) == 10
    floor = np.array([0.0, 0.0, 1.0])  # no downhill: world x
    np.testing.assert_allclose(Push(0, 0.1, (10.0, 0, 0)).world_force(floor), [10.0, 0, 0])


def test_each_scenario_draws_its_own_push_within_the_window():
    climbs = [Scenario(robot="hexa", seconds=2.0, seed=k) for k in range(20)]
    pushes = [reference_push(s, 100.0, 0.1) for s in climbs]
    assert pushes == [reference_push(s, 100.0, 0.1) for s in climbs]  # deterministic
    assert len({p.force for p in pushes if p}) == len(climbs)
    for p in pushes:
        assert p is not None and 0.6 <= p.start_s <= 1.2 and p.duration_s == 0.1
        assert np.hypot(*p.force[:2]) == pytest.approx(100.0) and p.force[2] == 0.0
    assert reference_push(climbs[0], 0.0, 0.1) is None  # the v6 presets push not

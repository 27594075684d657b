"""The gait planner: Hermite swings, one leg at a time, base following, magnet timing."""

from __future__ import annotations

import numpy as np
import pytest

from symbench.core.robot.specs import load_robot
from symbench.core.sim.gait.plan import RELEASE, SETTLE, STANCE, SWING, TOUCHDOWN, hermite
from symbench.core.sim.scene.arena import Arena
from symbench.core.sim.scene.setup import Climb


def test_hermite_hits_ends_and_is_differentiated_right():
    p0, v0, p1, v1 = np.zeros(3), np.array([0.1, 0.2, 0.0]), np.array([0.05, 0.0, 0.05]), np.ones(3)
    duration, eps = 0.25, 1e-6
    np.testing.assert_allclose(hermite(p0, v0, p1, v1, 0.0, duration)[:2], [p0, v0], atol=1e-15)
    np.testing.assert_allclose(hermite(p0, v0, p1, v1, 1.0, duration)[:2], [p1, v1], atol=1e-15)
    for u in (0.2, 0.7):
        _, vel, acc = hermite(p0, v0, p1, v1, u, duration)
        ahead, behind = (
            hermite(p0, v0, p1, v1, u + eps, duration),
            hermite(p0, v0, p1, v1, u - eps, duration),
        )
        np.testing.assert_allclose((ahead[0] - behind[0]) / (2 * eps * duration), vel, atol=1e-7)
        np.testing.assert_allclose((ahead[1] - behind[1]) / (2 * eps * duration), acc, atol=1e-6)


@pytest.mark.parametrize("robot", ["magneto", "hexa"])
def test_one_leg_at_a_time_full_steps_base_follows(robot):
    spec = load_robot(robot)
    climb = Climb(spec, Arena(60.0, 30.0), yaw_deg=15.0, direction_deg=90.0)
    plan = climb.plan()
    g, n = spec.gait, spec.n_legs
    slot = g.step_duration
    for k in range(n):  # slot k moves leg k (default order), one full step
        t0 = SETTLE + k * slot
        lift, land = t0 + g.release, t0 + g.release + g.swing
        during = plan.targets(t0 + 0.5 * g.release)
        assert during.step_leg == k and during.phase[k] == RELEASE and during.magnet[k] == 0
        assert (during.phase[np.arange(n) != k] == STANCE).all()
        start = plan.targets(lift + 1e-9).sole_pos
        top = plan.targets(lift + g.swing / 2)
        assert top.phase[k] == SWING
        assert (top.sole_pos - start) @ plan.normal == pytest.approx(g.swing_height)
        goal = plan.targets(land - 1e-9)
        np.testing.assert_allclose(goal.sole_pos - start, g.step_length * plan.direction, atol=1e-6)
        np.testing.assert_allclose(goal.sole_vel, 0.0, atol=1e-5)
        assert plan.targets(land + 0.01).phase[k] == TOUCHDOWN
    # the base moves step_length / n per slot, along the commanded (body-frame) direction
    moved = plan.targets(SETTLE + 2 * slot).base_pos - plan.targets(SETTLE).base_pos
    np.testing.assert_allclose(moved, 2 * g.step_length / n * plan.direction, atol=1e-12)
    np.testing.assert_allclose(plan.direction, climb.base_rotation[:, 1], atol=1e-12)  # "left"

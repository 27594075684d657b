"""The control loop's cached and bound fast paths give exactly what the plain code gives.

The standard datasets' content hashes depend on every bit of the simulation, so the speed-ups
of the loop (plan caches, probes bound to one MjData, precomputed views) must not change a
single value; the committed-hash tests (tests/data/test_same_data_on_every_cpu.py) check the
whole, these check the parts, bit for bit.
"""

from __future__ import annotations

import numpy as np
import pytest

from symbench.core.robot.specs import load_robot
from symbench.core.sim.arena import Arena
from symbench.core.sim.controller import _diagonal_blocks
from symbench.core.sim.gait import SETTLE, GaitPlan, hermite, hermite_at, hermite_points
from symbench.core.sim.setup import Climb
from symbench.core.sim.task import load_climb

FIELDS = ("phase", "magnet", "base_pos", "base_vel", "base_acc", "sole_pos", "sole_vel", "sole_acc")


def _fresh(plan: GaitPlan) -> GaitPlan:
    """The same plan without anything cached."""
    return GaitPlan(
        plan.spec, plan.order, plan.direction, plan.normal, plan.base_start, plan.soles_start
    )


def _same(a, b) -> bool:
    return all(np.array_equal(getattr(a, f), getattr(b, f)) for f in FIELDS) and (
        a.slot,
        a.step_leg,
    ) == (b.slot, b.step_leg)


@pytest.mark.parametrize("robot", ["magneto", "nona"])
def test_cached_plan_matches_a_fresh_plan_in_any_order(robot):
    plan = Climb(load_robot(robot), Arena(60.0, 30.0), yaw_deg=15.0).plan()
    slot = plan.slot
    times = SETTLE + slot * np.array([0.1, 0.5, 0.9, 2.5, 0.6, 0.55, 3.3, 0.7, -0.5, 0.05])
    for t in times:  # out of order: the caches must follow slot and swing changes
        assert _same(plan.targets(float(t)), _fresh(plan).targets(float(t)))


def test_a_new_liftoff_in_the_same_slot_is_not_served_from_the_cache():
    plan = Climb(load_robot("hexa"), Arena(90.0, 0.0)).plan()
    g = plan.spec.gait
    t = SETTLE + g.release + 0.3 * g.swing  # leg 0 swinging
    start = plan.targets(t).sole_pos  # the planned start, mid swing
    first = plan.soles_start[0] + np.array([0.001, 0.0, 0.0])
    second = plan.soles_start[0] - np.array([0.001, 0.0, 0.0])
    for liftoff in (first, second, first.copy()):
        assert _same(plan.targets(t, liftoff), _fresh(plan).targets(t, liftoff))
    assert not np.array_equal(plan.targets(t, first).sole_pos, start)


def test_hermite_split_is_the_same_arithmetic():
    rng = np.random.default_rng(3)
    p0, v0, p1, v1 = rng.normal(size=(4, 3))
    for u in (0.0, 0.3, 0.77, 1.0):
        points = hermite_points(p0, v0, p1, v1, 0.125)
        for a, b in zip(hermite(p0, v0, p1, v1, u, 0.125), hermite_at(points, u, 0.125)):
            assert np.array_equal(a, b)


def test_diagonal_block_view_writes_only_the_diagonal_blocks():
    n, k = 4, 3
    matrix = np.zeros((7 + n * k, 2 + n * k))[7:, 2:]  # a view, like the QP's torque rows
    blocks = _diagonal_blocks(matrix, n, k)
    values = np.arange(n * k * k, dtype=float).reshape(n, k, k) + 1.0
    blocks[...] = values
    expected = np.zeros((n * k, n * k))
    for i in range(n):
        expected[i * k : (i + 1) * k, i * k : (i + 1) * k] = values[i]
    assert np.array_equal(matrix, expected)


@pytest.mark.parametrize("robot", ["magneto", "hexa", "nona"])
def test_bound_probe_reads_what_the_layout_reads(robot):
    env = load_climb(Climb(load_robot(robot), Arena(90.0, 0.0), yaw_deg=20.0), time_limit=1.0)
    env.reset()
    physics = env.physics
    model, data, lay = physics.model.ptr, physics.data.ptr, physics.layout
    probe = lay.probe(model, data)
    rng = np.random.default_rng(0)
    for _ in range(3):  # the bound views follow the data as it changes
        data.qpos[7:] += rng.normal(scale=0.05, size=model.nq - 7)
        physics.forward()
        distance, clearance = probe.both()
        assert distance.tobytes() == lay.sole_distances(model, data).tobytes()
        assert clearance.tobytes() == lay.pad_clearances(data).tobytes()
        assert distance.tobytes() == probe.sole_distances().tobytes()
        assert clearance.tobytes() == probe.pad_clearances().tobytes()

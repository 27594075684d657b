"""The compiled parts of the climbing loop compute what their plain definitions say.

The loop runs compiled (symbench/core/sim/*_kernel.py); each piece is checked here against
an independent numpy statement of the same quantity: the surface probe against the plane
geometry, the fall judgement against its four rules, the gait plan's liftoff rule, the leg
inverse kinematics against forward kinematics, and the controller's QP against the
dynamics it must satisfy at a real state.
"""

from __future__ import annotations

import mujoco
import numpy as np
import pytest

from symbench.core.robot.specs import load_robot
from symbench.core.sim.contact.kernel import (
    DIVERGED,
    DROPPED,
    FOOT_LOST,
    HOLDING,
    TILTED,
    hold_state,
)
from symbench.core.sim.control.kinematics import leg_fk, leg_ik
from symbench.core.sim.gait.plan import SETTLE, SWING
from symbench.core.sim.scene.arena import Arena
from symbench.core.sim.scene.mjcf import PAD_SPHERE_RADIUS
from symbench.core.sim.scene.setup import Climb
from symbench.core.sim.scene.task import load_climb


def _physics(robot: str, yaw: float = 20.0):
    env = load_climb(Climb(load_robot(robot), Arena(90.0, 0.0), yaw_deg=yaw), time_limit=1.0)
    env.reset()
    return env.physics


@pytest.mark.parametrize("robot", ["magneto", "hexa", "nona"])
def test_probe_measures_the_pads_against_the_plane(robot):
    physics = _physics(robot)
    model, data, lay = physics.model.ptr, physics.data.ptr, physics.layout
    probe = lay.probe(model, data)
    rng = np.random.default_rng(0)
    for _ in range(3):  # the bound arrays follow the data as it changes
        data.qpos[7:] += rng.normal(scale=0.05, size=model.nq - 7)
        physics.forward()
        distance, clearance = probe.both()
        origin = data.geom_xpos[lay.surface_geom]
        normal = data.geom_xmat[lay.surface_geom].reshape(3, 3)[:, 2]
        pads = (data.geom_xpos[lay.pad_geom] - origin) @ normal
        np.testing.assert_allclose(clearance, pads.min(axis=1) - PAD_SPHERE_RADIUS, atol=1e-14)
        axis = data.geom_xmat[lay.sole_geom].reshape(-1, 3, 3)[:, :, 2] @ normal
        radius, half = model.geom_size[lay.sole_geom, 0], model.geom_size[lay.sole_geom, 1]
        height = (data.geom_xpos[lay.sole_geom] - origin) @ normal
        lowest = height - half * np.abs(axis) - radius * np.sqrt(1 - axis**2)
        np.testing.assert_allclose(distance, lowest, atol=1e-14)


def test_fall_rules_each_fire():
    qacc, qpos = np.zeros(12), np.array([0.0, 0.0, 0.1, 1, 0, 0, 0])
    xmat = np.tile(np.eye(3).ravel(), (2, 1))
    normal, stance, contact = np.array([0.0, 0.0, 1.0]), np.ones(4, bool), np.ones(4, bool)

    def judge(**change):
        a = {"qacc": qacc, "qpos": qpos, "xmat": xmat, "contact": contact, **change}
        return hold_state(
            a["qacc"], a["qpos"], a["xmat"], 1, stance, a["contact"], normal, 0.05, 0.866
        )

    assert judge() == HOLDING
    assert judge(qacc=np.full(12, np.nan)) == DIVERGED
    assert judge(contact=np.array([True, False, True, True])) == FOOT_LOST
    tilted = xmat.copy()
    tilted[1] = [1, 0, 0, 0, np.cos(0.6), -np.sin(0.6), 0, np.sin(0.6), np.cos(0.6)]
    assert judge(xmat=tilted) == TILTED
    assert judge(qpos=np.array([0.0, 0.0, 0.04, 1, 0, 0, 0])) == DROPPED


def test_a_liftoff_moves_the_swing_only_in_its_own_slot():
    plan = Climb(load_robot("hexa"), Arena(90.0, 0.0)).plan()
    g = plan.spec.gait
    t = SETTLE + g.release + 0.3 * g.swing  # slot 0: leg 0 swinging
    planned = plan.targets(t)
    assert planned.phase[0] == SWING and planned.slot == 0
    liftoff = plan.soles_start[0] + np.array([0.001, 0.0, 0.0])
    moved = plan.targets(t, liftoff, liftoff_slot=0)
    assert not np.allclose(moved.sole_pos, planned.sole_pos)
    stale = plan.targets(t, liftoff, liftoff_slot=3)  # released in another slot: ignored
    np.testing.assert_array_equal(stale.sole, planned.sole)


@pytest.mark.parametrize("robot", ["magneto", "nona"])
def test_leg_ik_inverts_leg_fk(robot):
    spec = load_robot(robot)
    rng = np.random.default_rng(1)
    q = np.stack(
        [rng.uniform(-0.8, 0.8, 50), rng.uniform(-0.5, 0.9, 50), rng.uniform(-2.0, -0.3, 50)],
        axis=-1,
    )
    np.testing.assert_allclose(leg_ik(spec, leg_fk(spec, q)), q, atol=1e-10)


@pytest.mark.parametrize("robot", ["magneto", "hexa", "nona"])
def test_the_qp_solution_obeys_the_floating_base_dynamics(robot):
    """At a real state, the controller's QP answer satisfies its equality rows to the
    solver's tolerance and every inequality (friction pyramids, torque limits), and the
    mass matrix the compiled code asked MuJoCo for is MuJoCo's."""
    from symbench.core.sim.control import kernel as control_kernel
    from symbench.core.sim.control.controller import WholeBodyController

    physics = _physics(robot, yaw=35.0)
    model, data, lay = physics.model.ptr, physics.data.ptr, physics.layout
    climb = Climb(load_robot(robot), Arena(90.0, 0.0), yaw_deg=35.0)
    controller = WholeBodyController(climb.spec, model, lay, climb.plan(), climb.base_rotation)
    n = climb.spec.n_legs
    out = (np.zeros(n, np.int64), np.zeros(n), np.zeros((3, 3)), np.zeros((3, 3)))
    out += (np.zeros((n, 3)), np.zeros((n, 3)))
    touching = np.ones(n, bool)
    *_, status = control_kernel.control_step(
        SETTLE + 0.01, touching, *controller.kernel_args(data), out
    )
    assert status >= 1
    cons, lower, upper = controller.qp.kernel_args[0][2:5]
    x = controller.qp.x
    rows = cons @ x
    assert np.all(rows >= lower - 1e-8) and np.all(rows <= upper + 1e-8)
    np.testing.assert_allclose(rows[:6], lower[:6], atol=1e-8)  # the equalities
    full = np.zeros((model.nv, model.nv))
    mujoco.mj_fullM(model, data, full)  # the compiled call of the same C function agrees
    np.testing.assert_array_equal(controller.kernel_args(data)[2][0], full)

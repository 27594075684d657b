"""The generated MJCF agrees with the spec: joints, actuators, leg frames, kinematics."""

from __future__ import annotations

import mujoco
import numpy as np
import pytest

from symbench.core.robot.specs import load_robot
from symbench.core.sim.control.kinematics import leg_fk, leg_ik
from symbench.core.sim.scene.arena import Arena
from symbench.core.sim.scene.layout import ModelLayout
from symbench.core.sim.scene.mjcf import compile_model

ROBOTS = ("magneto", "hexa", "nona")


@pytest.fixture(scope="module", params=ROBOTS)
def built(request):
    spec = load_robot(request.param)
    model = compile_model(spec, Arena(0.0, 0.0))
    return spec, model, ModelLayout.of(model, spec)


def test_model_sizes(built):
    spec, model, _ = built
    n = spec.n_legs
    assert model.nu == 4 * n  # three servos and one magnet per leg
    assert model.nv == 6 + 6 * n  # free base, three actuated and three gimbal joints per leg
    assert model.opt.solver == mujoco.mjtSolver.mjSOL_NEWTON
    assert model.opt.noslip_iterations == 0
    adhesion = [i for i in range(model.nu) if model.actuator_trntype[i] == mujoco.mjtTrn.mjTRN_BODY]
    assert len(adhesion) == n
    np.testing.assert_allclose(
        model.actuator_gear[adhesion, 0] * model.actuator_gainprm[adhesion, 0], spec.magnet.force
    )
    total = model.body_subtreemass[model.body("base").id]
    assert total == pytest.approx(spec.total_mass)


def test_leg_frames_match_the_spec(built):
    """Coxa joint positions and axes in the base frame are the spec's leg frames."""
    spec, model, lay = built
    data = mujoco.MjData(model)
    data.qpos[3] = 1.0
    mujoco.mj_forward(model, data)
    r_base = data.xmat[lay.base_body].reshape(3, 3)
    coxa = [model.body(f"leg{i}_coxa").id for i in range(spec.n_legs)]
    origins = (data.xpos[coxa] - data.xpos[lay.base_body]) @ r_base
    np.testing.assert_allclose(origins, spec.leg_origins(), atol=1e-12)
    frames = np.stack([r_base.T @ data.xmat[b].reshape(3, 3) for b in coxa])
    np.testing.assert_allclose(frames, spec.leg_rotations(), atol=1e-12)


def test_kinematics_match_mujoco(built):
    spec, model, lay = built
    data = mujoco.MjData(model)
    data.qpos[3] = 1.0
    rng = np.random.default_rng(0)
    lo, hi = spec.joint_limits()
    q = rng.uniform(lo, hi, size=(spec.n_legs, 3)) * 0.8
    data.qpos[lay.qpos] = q
    mujoco.mj_forward(model, data)
    ankle_body = data.xpos[lay.ankle_body] - data.xpos[lay.base_body]
    expect = np.einsum("nij,nj->ni", spec.leg_rotations(), leg_fk(spec, q)) + spec.leg_origins()
    np.testing.assert_allclose(ankle_body, expect, atol=1e-12)
    jac = np.zeros((3, model.nv))
    mujoco.mj_jac(model, data, jac, None, data.xpos[lay.ankle_body[0]], lay.ankle_body[0])
    in_leg = spec.leg_rotations()[0].T @ jac[:, lay.dof[0]]
    eps = 1e-7
    numeric = np.stack(
        [
            (leg_fk(spec, q[0] + eps * e) - leg_fk(spec, q[0] - eps * e)) / (2 * eps)
            for e in np.eye(3)
        ],
        axis=1,
    )
    np.testing.assert_allclose(in_leg, numeric, atol=1e-8)


def test_ik_inverts_fk():
    spec = load_robot("hexa")
    rng = np.random.default_rng(1)
    q = np.stack(
        [rng.uniform(-1, 1, 50), rng.uniform(-0.5, 1.2, 50), rng.uniform(-2.3, -0.2, 50)], 1
    )
    np.testing.assert_allclose(leg_ik(spec, leg_fk(spec, q)), q, atol=1e-10)

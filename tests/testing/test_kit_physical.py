"""The kit tests the physical claim: a model reading a feature in the wrong frame passes a
leg-permutation check and fails the raw-state one; the controls fail; the model's own
symmetry group is measured against the robot's."""

from __future__ import annotations

import numpy as np
import pytest
from broken_models import MISFRAMED

from symbench.core.data.views.model_dims import dims_for
from symbench.core.plugin import registry
from symbench.core.training.normalization import TARGET_KEY, Normalizer
from symbench.testing import (
    ControlPassedError,
    check_model,
    control_transforms,
    element_errors,
    measure_symmetry_group,
    robot_frames,
    robot_group,
    synthetic_raw_states,
)
from symbench.testing.equivariance import model_predictors


def plain_normalizer(n_legs: int) -> Normalizer:
    """Identity statistics: the misframed model's only fault is then its frame."""
    d = dims_for("vector", "acc", n_legs).shape("x")[-1]
    return Normalizer({"x": (np.zeros(d), np.ones(d)), TARGET_KEY: (np.zeros(3), np.ones(3))})


@pytest.mark.parametrize("robot", ["magneto", "hexa"])
def test_a_misframed_model_passes_the_permutation_check_and_fails_the_physical_one(robot):
    n = robot_group(robot).n_legs
    predict = model_predictors(MISFRAMED, n, normalizer=plain_normalizer(n))["float64"]
    world = np.random.default_rng(3).normal(size=16)

    def per_leg(x):  # the old check: random per-leg inputs whose legs are permuted
        joints = x[..., :9].reshape(len(x), n, 3, 3).transpose(0, 2, 1, 3).reshape(len(x), -1)
        flags = x[..., 9:].transpose(0, 2, 1).reshape(len(x), -1)
        return predict({"x": np.concatenate([np.tile(world, (len(x), 1)), joints, flags], 1)})

    old = element_errors({"float64": per_leg}, robot_group(robot), 11)
    assert max(e.errors["float64"] for e in old) < 1e-12  # passes: it cannot see frames
    report = check_model(MISFRAMED, robot, normalizer=plain_normalizer(n))
    assert report.claims and not report.passed
    assert all(e.errors["float64"] > 1e-2 for e in report.elements[1:])
    group = measure_symmetry_group(MISFRAMED, robot, normalizer=plain_normalizer(n))
    assert group.full_symmetric  # relabelling alone never catches it


def test_controls_fail_and_a_passing_control_raises():
    group, frames = robot_group("hexa"), robot_frames("hexa")
    raw = synthetic_raw_states("hexa", 4).raw
    names = [name for name, _, _ in control_transforms(group, frames, raw)]
    assert names.count("inverse rotation") == 4  # not for the half turn, its own inverse
    assert len(names) == 14
    report = check_model(registry.model("sdnn", "torch"), "hexa", hyper={"latent": 8})
    assert report.equivariant and report.controls_failed
    assert min(c.errors["float64"] for c in report.controls) > 1e-2
    zeros = {k: np.zeros_like(v) for k, v in report_params("hexa").items()}
    with pytest.raises(ControlPassedError, match="could not have failed"):
        check_model(registry.model("sdnn", "torch"), "hexa", hyper={"latent": 8}, params=zeros)


def report_params(robot: str) -> dict:
    from symbench.core.training.backends import get_backend

    entry = registry.model("sdnn", "torch")
    dims = dims_for(entry.view, entry.variant, robot_group(robot).n_legs)
    return get_backend("torch").init_params(entry, dims, {"latent": 8}, 0)


def test_plausible_raw_states_of_any_robot():
    states = synthetic_raw_states("nona", 5, seed=1)
    assert states.n_samples == 5 and states.raw["q"].shape == (10, 9, 3)
    assert np.allclose(np.linalg.norm(states.raw["base_quat"], axis=1), 1.0)


@pytest.mark.parametrize(
    ("name", "robot", "order", "over"),
    [
        ("sdnn", "magneto", 24, True),
        ("sdgnn", "hexa", 720, True),
        ("gnn", "hexa", 720, True),
        ("ffnn", "hexa", 1, False),
        ("sdnn", "nona", 362880, True),
    ],
)
def test_measured_symmetry_groups(name, robot, order, over):
    report = measure_symmetry_group(registry.model(name, "torch"), robot)
    assert report.order == order
    assert report.to_dict()["over_constrained"] is over
    assert report.legs_alike is (robot != "magneto")

"""The equivariance kit: the symmetric models pass, the others are reported, a liar is caught."""

from __future__ import annotations

import numpy as np
import pytest
from broken_models import ENTRIES as BROKEN

from symbench.core.data.views import schema
from symbench.core.plugin import registry
from symbench.core.symmetry.groups import cyclic, dihedral
from symbench.testing import (
    TOLERANCES,
    assert_equivariant,
    check_model,
    element_errors,
    robot_group,
)


def _every_robot_and_backend():
    """Every (model, backend, robot); JAX's graph network on magneto and nona under -m slow
    (XLA compiles it for 20 s each on 2 cores; hexa's stays in the default suite)."""
    for name in ("sdnn", "sdgnn"):
        for backend in ("torch", "jax"):
            for robot in ("magneto", "hexa", "nona"):
                slow = name == "sdgnn" and backend == "jax" and robot != "hexa"
                yield pytest.param(name, backend, robot, marks=[pytest.mark.slow] if slow else [])


@pytest.mark.parametrize(("name", "backend", "robot"), list(_every_robot_and_backend()))
def test_symmetric_models_pass_on_every_robot(name, backend, robot):
    group = robot_group(robot)
    report = assert_equivariant(registry.model(name, backend), group)
    assert len(report.elements) == group.order == {"magneto": 2, "hexa": 6, "nona": 9}[robot]
    assert report.max_error("float64") <= 1e-10 and report.max_error("float32") <= 1e-5
    assert report.passed


@pytest.mark.parametrize("name", ["ffnn", "ffnn-leg", "gnn"])
def test_models_claiming_nothing_are_reported_not_equivariant(name):
    report = check_model(registry.model(name, "torch"), robot_group("hexa"))
    assert not report.equivariant and report.passed
    assert report.verdict.startswith("not equivariant (claims none): measured max error")
    assert report.max_error("float64") > 1e-2  # every view is measured, and the error is large
    assert report.controls_failed


@pytest.mark.parametrize("entry", BROKEN, ids=lambda e: e.backend)
def test_the_kit_catches_a_model_that_claims_equivariance_and_breaks_it(entry):
    report = check_model(entry, cyclic(6))
    assert report.claims and not report.equivariant and not report.passed
    assert report.elements[0].errors["float64"] < 1e-14  # the identity cannot break anything
    assert all(e.errors["float64"] > 1e-4 for e in report.elements[1:])
    with pytest.raises(AssertionError, match="BROKEN"):
        assert_equivariant(entry, cyclic(6))


def test_reflections_act_with_the_feature_signs():
    """Per-leg joint angles as 'torques' follow the joint-scalar signs: equivariant under D6;
    sdnn, blind to the signs, is not."""
    layout = schema.leg_grouped_input("acc")
    q = layout.slice("q")

    def joint_angles(x):
        return x[..., q]

    group = dihedral(6)
    errors = element_errors(
        {"float64": joint_angles},
        group,
        layout.size,
        layout.reflection_signs,
        schema.TARGET.reflection_signs,
    )
    assert len(errors) == 12 and max(e.errors["float64"] for e in errors) == 0.0
    report = check_model(registry.model("sdnn", "torch"), group, hyper={"latent": 16})
    assert not report.equivariant
    assert all(e.errors["float64"] < 1e-10 for e in report.elements if not e.reflect)
    assert all(e.errors["float64"] > 1e-3 for e in report.elements if e.reflect)


def test_float32_errors_are_measured_separately():
    report = check_model(registry.model("sdnn", "torch"), cyclic(4, 2), hyper={"latent": 16})
    shift = report.elements[1].errors
    assert shift["float64"] < 1e-12 < shift["float32"] < TOLERANCES["float32"]


def test_report_serializes():
    report = check_model(registry.model("gnn", "torch"), robot_group("nona"))
    d = report.to_dict()
    assert d["claims_equivariance"] is False and d["passed"] and d["max_error"]["float64"] > 0.01
    assert d["controls"] and all(c["failed_as_it_must"] for c in d["controls"])
    assert np.isfinite(
        check_model(registry.model("sdnn", "torch"), cyclic(4, 2), hyper={"latent": 8}).to_dict()[
            "max_error"
        ]["float32"]
    )

"""Mirror groups in the kit and the symmetric models: sdnn and sdgnn averaged with their
leg-mirrored image (`mirror=1`) are equivariant to each robot's geometry group (K4, D6, D9),
checked on raw states over every element; the plain networks break on the mirrors only."""

from __future__ import annotations

import dataclasses
import json

import pytest
from cli_invoke import error_line, invoke

from symbench.core.data.views.frames import LegFrames
from symbench.core.plugin import registry
from symbench.core.robot.specs import load_robot
from symbench.testing import robot_frames, robot_geometry_group
from symbench.testing.equivariance import check_model

GEOMETRY = {"magneto": "K4", "hexa": "D6", "nona": "D9"}


def geometry_check(model: str, robot: str, mirror: int, backend: str = "torch", variant="acc"):
    spec = load_robot(robot)
    return check_model(
        dataclasses.replace(registry.model(model, backend), variant=variant),
        spec.geometry_group,
        frames=LegFrames.from_spec(spec),
        hyper={"mirror": mirror, **({"steps": 1} if model == "sdgnn" else {})},
    )


@pytest.mark.parametrize("robot", GEOMETRY)
@pytest.mark.parametrize("model", ["sdnn", "sdgnn"])
def test_mirror_averaged_models_are_equivariant_to_the_geometry_group(model, robot):
    report = geometry_check(model, robot, mirror=1)
    assert report.group == GEOMETRY[robot]
    assert sum(e.reflect for e in report.elements) == len(report.elements) // 2 > 0
    assert report.equivariant and report.controls_failed
    mirror_controls = [c for c in report.controls if c.element.startswith("mirror")]
    assert mirror_controls and all(min(c.errors.values()) > 0.05 for c in mirror_controls)


@pytest.mark.parametrize("robot", GEOMETRY)
def test_the_plain_network_breaks_on_the_mirrors_only(robot):
    report = geometry_check("sdnn", robot, mirror=0)
    assert not report.equivariant
    for element in report.elements:
        worst = max(element.errors.values())
        assert (worst > 0.1) if element.reflect else (worst < 1e-5), element


@pytest.mark.parametrize("model", ["sdnn", "sdgnn"])
def test_the_next_variant_the_closed_loop_uses_is_mirror_equivariant_too(model):
    """Its inputs carry the desired next state: the signs come from its own layout."""
    report = geometry_check(model, "hexa", mirror=1, variant="next")
    assert report.equivariant and report.controls_failed


def test_the_jax_twin_is_equivariant_to_the_mirrors_too():
    assert geometry_check("sdnn", "hexa", mirror=1, backend="jax").equivariant


def test_the_kit_api_gives_the_geometry_group_for_a_plugin_author():
    entry = registry.model("sdnn", "torch")
    group, frames = robot_geometry_group("nona"), robot_frames("nona")
    assert group.name == "D9"
    assert check_model(entry, group, frames=frames, hyper={"mirror": 1}).equivariant


def test_the_command_checks_the_geometry_group_with_a_size():
    command = ("check-equivariance", "--model", "sdnn", "--robot", "magneto", "--backend", "torch")
    result = invoke(*command, "--group", "geometry", "--size", "mirror=1", "--json")
    assert result.exit_code == 0, result.output
    (report,) = json.loads(result.stdout)
    assert report["group"] == "K4" and report["equivariant"]
    assert invoke(*command, "--group", "geometry").exit_code == 1  # plain sdnn claims it, breaks
    assert invoke(*command).exit_code == 0  # the declared group, C2: rotations only
    assert "'mirror' is not NAME=INT" in error_line(invoke(*command, "--size", "mirror"), 2)

"""`symbench sim check` verifies the robot's symmetry group in simulation, for any robot:
the run and its twin under each generator agree after relabelling, within the tolerance, or
the command exits 1 naming the broken generator."""

from __future__ import annotations

import json

import pytest
from cli_invoke import invoke

from symbench.core.plugin.entries import RobotEntry
from symbench.core.plugin.hookspecs import hookimpl
from symbench.core.plugin.host import PluginHost, set_host
from symbench.core.robot.specs import load_robot
from symbench.core.sim import setup
from symbench.core.sim.symmetry import TOLERANCE
from symbench.plugins.robots import ROBOTS_DIR


def sim_check(robot: str, *extra: str):
    return invoke("sim", "check", "--robot", robot, "--seconds", "0.5", *extra)


@pytest.mark.parametrize("robot", ["magneto", "hexa", "nona"])
def test_every_generator_of_a_built_in_robot_is_verified(robot):
    result = sim_check(robot, "--json")
    assert result.exit_code == 0, result.output
    symmetry = json.loads(result.output)["symmetry"]
    group = load_robot(robot).group
    assert [g["generator"] for g in symmetry["generators"]] == [g.name for g in group.generators]
    assert symmetry["seconds"] == 0.5 and symmetry["tolerance"] == TOLERANCE
    for g in symmetry["generators"]:
        assert g["simulated"] and g["error"] < 1e-9, g  # about 1e-11 over half a second
    assert symmetry["symmetric"]


def test_the_report_names_each_generator_and_its_error():
    result = sim_check("magneto")
    assert result.exit_code == 0, result.output
    lines = result.output.splitlines()
    assert "symmetry over 0.5 s" in lines[-2] and f"tolerance {TOLERANCE:g}" in lines[-2]
    assert lines[-1].startswith("    shift 2: error ") and lines[-1].endswith(" ok")


def test_a_broken_symmetry_fails_the_check(monkeypatch):
    """A twin turned without its gait carried along (the swing order not relabelled) is not
    the symmetric image of the run: the check has teeth."""
    turned = setup.Climb.turned

    def turned_without_the_gait(self, steps=1):
        return setup.replace(turned(self, steps), order=self.order)

    monkeypatch.setattr(setup.Climb, "turned", turned_without_the_gait)
    result = invoke("sim", "check", "--robot", "hexa", "--seconds", "1.2", "--json")
    assert result.exit_code == 1, result.output
    report = json.loads(result.output)
    assert report["attached"] and not report["symmetry"]["symmetric"]
    (generator,) = report["symmetry"]["generators"]
    assert generator["error"] > 1e-3 and not generator["within_tolerance"]
    assert "BROKEN" in invoke("sim", "check", "--robot", "hexa", "--seconds", "1.2").output


def test_symmetry_seconds_zero_skips_it_and_a_negative_value_is_an_error():
    result = sim_check("magneto", "--json", "--symmetry-seconds", "0")
    assert result.exit_code == 0 and "symmetry" not in json.loads(result.output)
    result = sim_check("magneto", "--symmetry-seconds", "-1")
    assert result.exit_code == 1 and "symmetry seconds" in result.output


@pytest.fixture
def dihedral_hexa(tmp_path):
    """A plugin robot declaring mirrors: hexa's spec with group D6."""
    text = (ROBOTS_DIR / "hexa" / "robot.toml").read_text()
    text = text.replace('name = "hexa"', 'name = "dihexa"').replace(
        'kind = "cyclic"', 'kind = "dihedral"\nmirror_offset = 0'
    )
    (tmp_path / "dihexa").mkdir()
    (tmp_path / "dihexa" / "robot.toml").write_text(text)

    class Plugin:
        @hookimpl
        def symbench_robots(self):
            return [RobotEntry("dihexa", tmp_path / "dihexa", "hexa declaring D6")]

    host = PluginHost()
    host.load_entry_points("none")
    host.register(Plugin(), "dihexa-plugin")
    set_host(host)
    yield "dihexa"
    set_host(None)


def test_a_plugin_robot_with_mirrors_gets_every_generator_reported(dihedral_hexa):
    result = sim_check(dihedral_hexa, "--json")
    assert result.exit_code == 0, result.output
    generators = json.loads(result.output)["symmetry"]["generators"]
    assert [g["generator"] for g in generators] == ["shift 1", "mirror 0"]
    rotation, mirror = generators
    assert rotation["simulated"] and rotation["error"] < 1e-9
    assert not mirror["simulated"] and "mirror" in mirror["note"]

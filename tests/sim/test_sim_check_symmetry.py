"""`symbench sim check` verifies the robot's symmetry group in simulation, for any robot:
the run and its twin under each generator (the declared rotations and the mirrors the
geometry has, or declares) agree after relabelling, within the tolerance, or the command
exits 1 naming the broken generator."""

from __future__ import annotations

import json

import pytest
from cli_invoke import invoke

from symbench.core.plugin.entries import RobotEntry
from symbench.core.plugin.hookspecs import hookimpl
from symbench.core.plugin.host import PluginHost, set_host
from symbench.core.robot.specs import load_robot
from symbench.core.sim.scene import setup
from symbench.core.sim.symmetry import TOLERANCE
from symbench.plugins.robots import ROBOTS_DIR


def sim_check(robot: str, *extra: str):
    return invoke("sim", "check", "--robot", robot, "--seconds", "0.5", *extra)


@pytest.mark.parametrize(
    "robot, geometry, generators",
    [
        ("magneto", "K4", ["shift 2", "mirror 1"]),
        ("hexa", "D6", ["shift 1", "mirror 0"]),
        ("nona", "D9", ["shift 1", "mirror 0"]),
    ],
)
def test_every_generator_of_a_built_in_robot_is_verified(robot, geometry, generators):
    """The declared rotation and the mirror found in the geometry, both simulated."""
    spec = load_robot(robot)
    assert spec.geometry_group.name == geometry and spec.geometry_group.has_reflections
    result = sim_check(robot, "--json")
    assert result.exit_code == 0, result.output
    symmetry = json.loads(result.output)["symmetry"]
    assert [g["generator"] for g in symmetry["generators"]] == generators
    assert [g["declared"] for g in symmetry["generators"]] == [True, False]
    assert symmetry["geometry_group"] == geometry
    assert symmetry["groups"] == f"{spec.group.name} declared, {geometry} from geometry"
    assert symmetry["seconds"] == 0.5 and symmetry["tolerance"] == TOLERANCE
    for g in symmetry["generators"]:
        assert g["error"] < 1e-9, g  # about 1e-11 over half a second
        assert set(g["columns"]) >= {"q", "tau", "base_pos", "base_angvel", "base_rotation"}
    assert symmetry["symmetric"]


def test_the_report_names_each_generator_and_its_error():
    result = sim_check("magneto")
    assert result.exit_code == 0, result.output
    lines = result.output.splitlines()
    assert "symmetry over 0.5 s of C2 declared, K4 from geometry: twin" in lines[-3]
    assert f"tolerance {TOLERANCE:g}" in lines[-3]
    assert lines[-2].startswith("    shift 2: error ") and lines[-2].endswith(" ok")
    assert lines[-1].startswith("    mirror 1 (geometry, not declared): error ")
    assert lines[-1].endswith(" ok")


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
    rotation, mirror = report["symmetry"]["generators"]
    assert rotation["error"] > 1e-3 and not rotation["within_tolerance"]
    assert mirror["within_tolerance"]  # the mirror twin does not turn: it stays symmetric
    assert "BROKEN" in invoke("sim", "check", "--robot", "hexa", "--seconds", "1.2").output


@pytest.mark.parametrize("robot", ["magneto", "hexa"])
def test_a_mirror_twin_with_its_start_not_mirrored_fails_the_check(monkeypatch, robot):
    """The seeded start perturbation (a slide across the slope, a twist) left unmirrored
    breaks the mirror image: only the mirror generator is reported broken."""
    reflected = setup.Climb.reflected

    def reflected_with_the_same_start(self, g):
        return setup.replace(reflected(self, g), mirrored=self.mirrored)

    monkeypatch.setattr(setup.Climb, "reflected", reflected_with_the_same_start)
    result = sim_check(robot, "--json")
    assert result.exit_code == 1, result.output
    rotation, mirror = json.loads(result.output)["symmetry"]["generators"]
    assert rotation["within_tolerance"]
    assert mirror["error"] > 1e-3 and not mirror["within_tolerance"]


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
    assert [g["declared"] for g in generators] == [True, True]
    assert all(g["error"] < 1e-9 and g["within_tolerance"] for g in generators)

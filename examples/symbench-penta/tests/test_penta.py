"""The plugin's own tests (run with the package installed): the robot is registered, its
spec loads from the installed package, and its group is C5 for symbench's kit."""

from __future__ import annotations

from symbench import load_robot
from symbench.testing import registered_robots, robot_group


def test_penta_is_registered_with_its_spec_inside_the_package():
    import symbench_penta

    assert "penta" in registered_robots()
    assert (symbench_penta.spec_dir() / "robot.toml").is_file()
    spec = load_robot("penta")
    assert spec.n_legs == 5 and spec.symmetry_angle_deg == 72.0


def test_penta_group_is_c5():
    group = robot_group("penta")
    assert group.order == 5 and group.rotation_order == 5 and not group.has_reflections


def test_the_kit_fixtures_cover_penta(symbench_groups):
    assert symbench_groups["penta"].n_legs == 5

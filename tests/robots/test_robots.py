"""Robot specs: loading, validation, and leg frames consistent with the symmetry group."""

from __future__ import annotations

import tomllib

import numpy as np
import pytest
from toml_writer import toml_text

from symbench.core.common.errors import SymbenchError
from symbench.core.robot.specs import load_robot, load_spec, parse_spec
from symbench.core.sim.scene.scenario import Scenario
from symbench.plugins.robots import ROBOTS_DIR

ROBOTS = {"magneto": (4, 2), "hexa": (6, 6), "nona": (9, 9)}


def rot_z(deg: float) -> np.ndarray:
    a = np.radians(deg)
    return np.array([[np.cos(a), -np.sin(a), 0], [np.sin(a), np.cos(a), 0], [0, 0, 1]])


@pytest.mark.parametrize("name", ROBOTS)
def test_spec_loads_with_group(name):
    spec = load_robot(name)
    n_legs, order = ROBOTS[name]
    assert spec.n_legs == n_legs and spec.group.order == order
    assert spec.leg_rotations().shape == (n_legs, 3, 3)
    assert spec.leg_origins().shape == (n_legs, 3)
    assert spec.torque_limits().shape == (3,)
    assert len(spec.spec_hash()) == 64


@pytest.mark.parametrize("name", ROBOTS)
def test_leg_frames_rotate_onto_each_other_under_the_group(name):
    """Rotating the base by the group's angle carries leg frame i onto leg frame i + shift."""
    spec = load_robot(name)
    rz = rot_z(spec.symmetry_angle_deg)
    k, n = spec.symmetry_shift, spec.n_legs
    rot, org = spec.leg_rotations(), spec.leg_origins()
    for i in range(n):
        j = (i + k) % n
        np.testing.assert_allclose(rz @ rot[i], rot[j], atol=1e-12)
        np.testing.assert_allclose(rz @ org[i], org[j], atol=1e-12)


@pytest.mark.parametrize("name", ROBOTS)
def test_legs_are_counter_clockwise(name):
    org = load_robot(name).leg_origins()
    ang = np.unwrap(np.arctan2(org[:, 1], org[:, 0]))
    assert np.all(np.diff(ang) > 0)


def test_bad_spec_names_the_entry(tmp_path):
    (tmp_path / "robot.toml").write_text('name = "x"\nn_legs = 3\n')
    with pytest.raises(SymbenchError, match="missing 'base'"):
        load_spec(tmp_path)
    with pytest.raises(SymbenchError, match="does not exist"):
        load_spec(tmp_path / "nope")


def test_wrong_mount_count_is_an_error():
    import tomllib

    from symbench.plugins.robots import ROBOTS_DIR

    raw = tomllib.loads((ROBOTS_DIR / "hexa" / "robot.toml").read_text())
    raw["mounts"]["angles_deg"] = raw["mounts"]["angles_deg"][:5]
    with pytest.raises(SymbenchError, match="angles_deg"):
        parse_spec(raw)


def test_unknown_robot_suggests_names():
    with pytest.raises(SymbenchError, match="hexa"):
        load_robot("hexaa")


def test_scenario_round_trip_and_validation():
    s = Scenario(
        "hexa", inclination_deg=60, heading_deg=90, yaw_deg=15, leg_order=(0, 2, 4, 1, 3, 5)
    )
    assert Scenario.from_dict(s.to_dict()) == s
    with pytest.raises(SymbenchError, match="inclination"):
        Scenario("hexa", inclination_deg=200)
    with pytest.raises(SymbenchError, match="direction"):
        Scenario("hexa", direction="up")
    with pytest.raises(SymbenchError, match="unknown field"):
        Scenario.from_dict({"robot": "hexa", "speed": 1})


def _spec_variant(tmp_path, replacements: dict[str, str]):
    from symbench.core.robot.specs import load_spec
    from symbench.plugins.robots import ROBOTS_DIR

    text = (ROBOTS_DIR / "hexa" / "robot.toml").read_text()
    for old, new in replacements.items():
        assert old in text
        text = text.replace(old, new)
    (tmp_path / "robot.toml").write_text(text)
    return lambda: load_spec(tmp_path)


def test_a_spec_whose_legs_lack_the_declared_symmetry_is_refused(tmp_path):
    load = _spec_variant(tmp_path, {"coxa_yaw_deg = [30.0,": "coxa_yaw_deg = [40.0,"})
    with pytest.raises(SymbenchError, match="declares group C6, but .* not symmetric"):
        load()


def test_a_spec_whose_base_lacks_the_declared_symmetry_is_refused(tmp_path):
    load = _spec_variant(
        tmp_path, {"inertia = [0.011005, 0.011005,": "inertia = [0.00834, 0.01367,"}
    )
    with pytest.raises(SymbenchError, match="equal x and y base.inertia"):
        load()


@pytest.mark.parametrize(
    "name, geometry, mirrors",
    [
        ("magneto", "K4", {(3, 2, 1, 0), (1, 0, 3, 2)}),
        ("hexa", "D6", {tuple((k - i) % 6 for i in range(6)) for k in range(6)}),
        ("nona", "D9", {tuple((k - i) % 9 for i in range(9)) for k in range(9)}),
    ],
)
def test_the_geometry_group_adds_the_mirrors_found_in_the_geometry(name, geometry, mirrors):
    """Each mirror carries leg frames onto (mirrored) leg frames and keeps the base's
    inertia and shape; magneto's unequal base inertia allows only its two axis mirrors."""
    spec = load_robot(name)
    group = spec.geometry_group
    assert group.name == geometry and group.order == 2 * spec.group.order
    assert {g.perm for g in group if g.reflect} == mirrors
    assert {g for g in group if not g.reflect} == set(spec.group)


def test_a_robot_with_skewed_coxas_has_rotations_but_no_mirror(tmp_path):
    """Coxas all turned 10 degrees off radial: the legs still rotate onto each other, but
    the robot is chiral, so its geometry group is the declared C6 alone."""
    skewed = ", ".join(f"{a + 10.0:.1f}" for a in range(30, 360, 60))
    spec = _spec_variant(
        tmp_path,
        {"coxa_yaw_deg = [30.0, 90.0, 150.0, 210.0, 270.0, 330.0]": f"coxa_yaw_deg = [{skewed}]"},
    )()
    assert spec.geometry_group is spec.group and not spec.group.has_reflections


def test_a_declared_mirror_the_geometry_lacks_is_refused(tmp_path):
    """magneto declaring a mirror through its diagonal legs (0 and 2): neither its mounts nor
    its base inertia have it."""
    text = (ROBOTS_DIR / "magneto" / "robot.toml").read_text()
    (tmp_path / "robot.toml").write_text(
        text.replace('kind = "cyclic"', 'kind = "dihedral"\nmirror_offset = 0')
    )
    with pytest.raises(SymbenchError, match="declares group D2, but .* not symmetric"):
        load_spec(tmp_path)


def test_a_declared_mirror_the_base_lacks_is_refused(tmp_path):
    """magneto's legs with a mirror at 45 degrees would need equal x and y base inertia."""
    text = (ROBOTS_DIR / "magneto" / "robot.toml").read_text()
    text = text.replace(
        "angles_deg = [37.234, 142.766, 217.234, 322.766]",
        "angles_deg = [45.0, 135.0, 225.0, 315.0]",
    )
    text = text.replace('kind = "cyclic"', 'kind = "dihedral"\nmirror_offset = 0')
    (tmp_path / "robot.toml").write_text(text)
    with pytest.raises(SymbenchError, match="base's inertia or shape is not symmetric"):
        load_spec(tmp_path)


def test_a_shift_that_is_not_the_smallest_rotation_is_refused(tmp_path):
    load = _spec_variant(tmp_path, {"shift = 1": "shift = 5"})
    with pytest.raises(SymbenchError, match="shift must be the legs per smallest rotation"):
        load()


def test_mounts_going_round_twice_are_refused(tmp_path):
    text = {
        "angles_deg = [30.0, 90.0, 150.0, 210.0, 270.0, 330.0]": (
            "angles_deg = [30.0, 150.0, 270.0, 390.0, 510.0, 630.0]"
        )
    }
    with pytest.raises(SymbenchError, match="once around"):
        _spec_variant(tmp_path, text)()


def test_a_missing_leg_table_is_named():
    import tomllib

    from symbench.plugins.robots import ROBOTS_DIR

    raw = tomllib.loads((ROBOTS_DIR / "hexa" / "robot.toml").read_text())
    del raw["leg"]["masses"]
    with pytest.raises(SymbenchError, match=r"x.toml \[leg\]: missing 'masses'"):
        parse_spec(raw, "x.toml")


@pytest.mark.parametrize(
    "table, key, value, message",
    [
        ("leg", "joint_damping", -0.1, "joint_damping: expected a non-negative number"),
        ("ankle", "stiffness", -1.0, "stiffness: expected a non-negative number"),
        ("ankle", "masses", [0.03, 0.0, 0.3], "masses: expected 3 positive numbers"),
        ("ankle", "lower", [-0.5, 0.5, -2.0], "lower limit must be below its upper"),
    ],
)
def test_physically_impossible_values_are_named(table, key, value, message):
    import tomllib

    from symbench.plugins.robots import ROBOTS_DIR

    raw = tomllib.loads((ROBOTS_DIR / "hexa" / "robot.toml").read_text())
    raw[table][key] = value
    with pytest.raises(SymbenchError, match=message):
        parse_spec(raw)


@pytest.mark.parametrize(
    ("edit", "message"),
    [
        (lambda raw: raw.update(n_legs="six"), "n_legs: expected an integer, got 'six'"),
        (lambda raw: raw.update(stance=0.5), "[stance] must be a table, got 0.5"),
        (lambda raw: raw["ankle"].update(inertias=True), "inertias needs 3 rows"),
        (lambda raw: raw["base"].update(mass=True), "base.mass: expected a number, got True"),
        (lambda raw: raw["mounts"].update(z="0.1"), "[mounts] z: expected a number, got '0.1'"),
        (lambda raw: raw["symmetry"].update(kind="cycli"), "[symmetry]: unknown symmetry group"),
    ],
    ids=[
        "text for a count",
        "number for a table",
        "flag for rows",
        "flag for a mass",
        "text for a number",
        "unknown group",
    ],
)
def test_a_value_of_another_type_is_refused_naming_the_file_and_entry(tmp_path, edit, message):
    """Before: ValueError or TypeError, internal errors (found by the property suite), a
    flag read as the number 1, and an unknown group named without its file."""
    raw = tomllib.loads((ROBOTS_DIR / "hexa" / "robot.toml").read_text())
    edit(raw)
    (tmp_path / "robot.toml").write_text(toml_text(raw))
    with pytest.raises(SymbenchError) as error:
        load_spec(tmp_path)
    assert str(error.value).startswith(str(tmp_path / "robot.toml")) and message in str(error.value)


def test_a_robot_toml_that_is_no_utf8_is_refused_naming_it(tmp_path):
    (tmp_path / "robot.toml").write_bytes(b"name = '\xff'\n")
    with pytest.raises(SymbenchError, match=r"robot.toml: not valid TOML \('utf-8' codec"):
        load_spec(tmp_path)

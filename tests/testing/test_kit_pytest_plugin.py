"""The pytest11 entry point provides the kit's fixtures to any test suite, for every
registered robot: the built-in ones and those of plugins."""

from __future__ import annotations

import textwrap

from symbench.core.plugin import registry
from symbench.core.plugin.entries import RobotEntry
from symbench.core.plugin.hookspecs import hookimpl
from symbench.core.plugin.host import PluginHost, set_host
from symbench.plugins.robots import ROBOTS_DIR
from symbench.testing import registered_robots, robot_groups

pytest_plugins = ["pytester"]


def test_fixtures_come_from_the_installed_plugin(symbench_kit, symbench_groups):
    assert set(symbench_groups) == set(registry.collect("robots")) >= {"magneto", "hexa", "nona"}
    assert symbench_kit.n_samples == 32
    report = symbench_kit.assert_equivariant(
        registry.model("sdnn", "torch"), symbench_groups["nona"], hyper={"latent": 8}
    )
    assert report.equivariant and len(report.elements) == 9


def test_one_test_per_registered_robot(symbench_robot, symbench_group):
    assert symbench_robot in registry.collect("robots")
    assert symbench_group.n_legs == {"magneto": 4, "hexa": 6, "nona": 9}.get(
        symbench_robot, symbench_group.n_legs
    )


def plugin_robot(tmp_path) -> PluginHost:
    """The built-ins plus a plugin robot 'octa-test': hexa's spec with 8 legs."""
    text = (ROBOTS_DIR / "hexa" / "robot.toml").read_text().replace('name = "hexa"', "")
    angles = ", ".join(f"{45.0 * i}" for i in range(8))
    lines = [
        line
        for line in text.splitlines()
        if not line.startswith(("n_legs", "angles_deg", "coxa_yaw_deg"))
    ]
    spec = "\n".join(lines).replace(
        "[mounts]", f"[mounts]\nangles_deg = [{angles}]\ncoxa_yaw_deg = [{angles}]"
    )
    (tmp_path / "octa-test").mkdir()
    (tmp_path / "octa-test" / "robot.toml").write_text(f'name = "octa-test"\nn_legs = 8\n{spec}\n')

    class Plugin:
        @hookimpl
        def symbench_robots(self):
            return [RobotEntry("octa-test", tmp_path / "octa-test", "test octopod")]

    host = PluginHost()
    host.load_entry_points("none")
    host.register(Plugin(), "octa-plugin")
    return host


def test_the_groups_include_plugin_robots(tmp_path):
    set_host(plugin_robot(tmp_path))
    try:
        assert registered_robots() == ("hexa", "magneto", "nona", "octa-test")
        groups = robot_groups()
    finally:
        set_host(None)
    assert groups["octa-test"].order == 8 and groups["octa-test"].n_legs == 8


def test_a_plugin_suite_gets_its_robot_through_the_fixtures(pytester, tmp_path):
    """A plugin's own test suite (here with the robot registered when the session starts)
    sees the plugin robot in `symbench_groups` and gets one `symbench_robot` test for it."""
    pytester.makepyfile(
        textwrap.dedent(
            """
            def test_groups(symbench_groups):
                assert "octa-test" in symbench_groups

            def test_each(symbench_robot, symbench_group):
                assert symbench_group.n_legs > 0
            """
        )
    )
    host = plugin_robot(tmp_path)

    class RegistersTheRobot:  # what the plugin's installation does for its suite
        @staticmethod
        def pytest_configure(config):
            set_host(host)

    try:
        result = pytester.runpytest_inprocess(
            "-v", "-p", "no:cacheprovider", plugins=[RegistersTheRobot()]
        )
    finally:
        set_host(None)
    result.assert_outcomes(passed=5)
    result.stdout.fnmatch_lines(["*test_each?octa-test?*PASSED*"])

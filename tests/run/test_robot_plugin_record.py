"""A record of a plugin's robot names the plugin, distribution and version that supplied it,
as a model's record names its plugin (issue 42, item 13)."""

from __future__ import annotations

import pytest

from symbench import RobotEntry, hookimpl
from symbench.core.plugin import registry
from symbench.core.plugin.host import PluginHost, get_host, set_host
from symbench.core.runs.results import RobotPlugin, read_record
from symbench.core.runs.runner import RunSpec, run


class MyRobots:
    """A third party's plugin shipping hexa's spec (so the session's smoke data serves it)."""

    def __init__(self, spec_dir) -> None:
        self.spec_dir = spec_dir

    @hookimpl
    def symbench_robots(self):
        return [RobotEntry("hexa", self.spec_dir, "hexa, from a plugin")]


@pytest.fixture
def plugin_robot():
    """The built-ins without their robots plugin; hexa registered by `my-robots` 0.3."""
    spec_dir = registry.robot("hexa", get_host()).spec_dir
    host = PluginHost()
    host.load_entry_points("none")
    host.pm.unregister(name="robots")
    del host.info["robots"]
    host.register(MyRobots(spec_dir), "my_robots", "my-robots", "0.3")
    set_host(host)
    yield
    set_host(None)


def test_a_record_of_a_plugin_robot_names_its_distribution_and_version(
    smoke_home, tmp_path, plugin_robot
):
    spec = RunSpec(
        model="ffnn",
        robot="hexa",
        preset="smoke",
        evaluators=("torque-error",),
        output=tmp_path,
        progress=False,
        max_steps=10,
    )
    run(spec)
    assert read_record(spec.record_path).robot_plugin == RobotPlugin(
        plugin="my_robots", distribution="my-robots", version="0.3"
    )

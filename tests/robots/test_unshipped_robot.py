"""A plugin's robot whose folder its wheel left out (no package-data) is registered all the
same: `symbench list robots` warns about it, and using it names the plugin and the
package-data glob that ships it (issue 42, item 11)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from click.testing import CliRunner

from symbench import RobotEntry, hookimpl
from symbench.core.cli import build_cli
from symbench.core.common.errors import SymbenchError
from symbench.core.plugin.host import PluginHost, set_host
from symbench.core.robot.specs import load_robot

FIX = '<package> = ["*/robot.toml", "*/README.md"]'


class WheelWithoutSpecs:
    """A plugin installed from a wheel that holds its code but not its robot folder."""

    def __init__(self, site: Path) -> None:
        self.site = site

    @hookimpl
    def symbench_robots(self):
        return [RobotEntry("tripod", self.site / "my_robots" / "tripod", "a 3-legged climber")]


@pytest.fixture
def host(tmp_path):
    host = PluginHost()
    host.load_entry_points("none")
    host.register(WheelWithoutSpecs(tmp_path), "my_robots", "my-robots", "0.3")
    set_host(host)
    yield tmp_path
    set_host(None)


def test_using_it_names_the_plugin_and_the_package_data_glob(host):
    with pytest.raises(SymbenchError) as error:
        load_robot("tripod")
    message = str(error.value)
    assert "robot 'tripod' of plugin 'my_robots' (my-robots 0.3)" in message
    assert str(host / "my_robots" / "tripod" / "robot.toml") in message
    assert "package-data" in message and FIX in message
    with pytest.raises(SymbenchError, match="package-data"):
        load_robot("tripod-asym-0.1")  # a variant of it too


def test_list_robots_warns_and_still_lists_it(host):
    result = CliRunner().invoke(build_cli(), ["list", "robots", "--json"])
    assert result.exit_code == 0
    assert "tripod" in [row["name"] for row in json.loads(result.stdout)]
    warnings = [line for line in result.stderr.splitlines() if line.startswith("warning:")]
    assert len(warnings) == 1
    assert "robot 'tripod' of plugin 'my_robots'" in warnings[0] and FIX in warnings[0]


def test_a_shipped_robot_is_listed_without_warning(host):
    (host / "my_robots" / "tripod").mkdir(parents=True)
    (host / "my_robots" / "tripod" / "robot.toml").write_text('name = "tripod"\n')
    result = CliRunner().invoke(build_cli(), ["list", "robots"])
    assert result.exit_code == 0 and "warning" not in result.stderr

"""The plugin system: every hook, in-process registration, broken plugins, restriction."""

from __future__ import annotations

import json
from importlib.metadata import EntryPoint
from pathlib import Path

import click
import pytest
from click.testing import CliRunner

from symbench import hookimpl
from symbench.core import plugins, registry
from symbench.core.cli import build_cli
from symbench.core.entries import EvaluatorEntry, ModelEntry, RobotEntry, SplitEntry
from symbench.core.errors import SymbenchError, UnknownNameError
from symbench.core.plugins import PluginHost, set_host


class ToyPlugin:
    """One implementation of every hook, as a third party would write it."""

    @hookimpl
    def symbench_models(self):
        return [ModelEntry("toy", "torch", "leg_grouped", "acc", True, build=lambda dims: None),
                ModelEntry("toy", "jax", "leg_grouped", "acc", True, build=lambda dims: None)]

    @hookimpl
    def symbench_robots(self):
        return [RobotEntry("tripod", Path("/nowhere/tripod"), "a three-legged test robot")]

    @hookimpl
    def symbench_evaluators(self):
        return [EvaluatorEntry("toy-metric", evaluate=lambda ctx: {"x": 1.0})]

    @hookimpl
    def symbench_splits(self):
        return [SplitEntry("toy-split", assign=lambda scenarios, seed: None)]

    @hookimpl
    def symbench_commands(self, cli: click.Group):
        @cli.command("toy-hello")
        def hello():
            """Say hello from a plugin."""
            click.echo("hello from toy")


class BrokenPlugin:
    @hookimpl
    def symbench_robots(self):
        raise RuntimeError("spec folder vanished")


@pytest.fixture
def host():
    h = PluginHost()
    set_host(h)
    yield h
    set_host(None)


def invoke(*args: str):
    return CliRunner().invoke(build_cli(), list(args), catch_exceptions=False)


def test_in_process_plugin_appears_in_every_list(host):
    host.register(ToyPlugin(), "toy")
    models = json.loads(invoke("list", "models", "--json").stdout)
    assert {(m["name"], m["backend"]) for m in models} == {("toy", "torch"), ("toy", "jax")}
    assert json.loads(invoke("list", "robots", "--json").stdout)[0]["name"] == "tripod"
    assert json.loads(invoke("list", "evaluators", "--json").stdout)[0]["name"] == "toy-metric"
    assert json.loads(invoke("list", "splits", "--json").stdout)[0]["name"] == "toy-split"
    table = invoke("list", "models")
    assert table.exit_code == 0 and "toy" in table.stdout


def test_symbench_commands_hook_adds_a_command(host):
    host.register(ToyPlugin(), "toy")
    assert "toy-hello" in invoke("--help").stdout
    assert invoke("toy-hello").stdout.strip() == "hello from toy"


def test_broken_plugin_is_named_and_others_keep_working(host):
    host.register(ToyPlugin(), "toy")
    host.register(BrokenPlugin(), "broken-robots")
    result = invoke("list", "robots", "--json")
    assert result.exit_code == 0
    assert [r["name"] for r in json.loads(result.stdout)] == ["tripod"]
    assert "broken-robots" in result.stderr and "spec folder vanished" in result.stderr
    described = json.loads(invoke("plugins").stdout)
    assert {"plugin": "broken-robots", "where": "symbench_robots",
            "error": "RuntimeError: spec folder vanished"} in described["problems"]
    assert invoke("list", "models", "--json").exit_code == 0


def test_plugin_that_fails_to_import_is_named(monkeypatch):
    broken = EntryPoint("ghost", "symbench_no_such_module_xyz", "symbench")
    monkeypatch.setattr(plugins, "entry_points", lambda group: [broken])
    h = PluginHost()
    h.load_entry_points(allowed="all")
    assert [p.plugin for p in h.problems] == ["ghost"]
    assert "ModuleNotFoundError" in h.problems[0].error and h.problems[0].where == "import"


@pytest.mark.parametrize("allowed,loaded", [("all", True), ("none", False), ("", False),
                                            ("other,tester", True), ("other", False)])
def test_environment_variable_restricts_third_party(monkeypatch, allowed, loaded):
    ep = EntryPoint("tester", "symbench.core.errors", "symbench")
    monkeypatch.setattr(plugins, "entry_points", lambda group: [ep])
    monkeypatch.setenv(plugins.ENV_VAR, allowed)
    h = PluginHost()
    h.load_entry_points()
    assert ("tester" in h.info) is loaded


def test_wrong_type_and_duplicates_are_problems_of_the_plugin(host):
    class Twice:
        @hookimpl
        def symbench_splits(self):
            return [SplitEntry("toy-split", assign=lambda s, seed: None), "not an entry"]

    host.register(ToyPlugin(), "toy")
    host.register(Twice(), "twice")
    splits = registry.collect("splits", host)
    assert list(splits) == ["toy-split"]
    messages = [str(p) for p in host.problems]
    assert any("twice" in m and "already registered by 'toy'" in m for m in messages)
    assert any("twice" in m and "expected SplitEntry" in m for m in messages)


def test_unknown_names_get_the_closest(host):
    host.register(ToyPlugin(), "toy")
    with pytest.raises(UnknownNameError, match="did you mean toy"):
        registry.model("tay", "torch", host)
    with pytest.raises(SymbenchError, match="no 'flax' backend"):
        registry.model("toy", "flax", host)
    with pytest.raises(UnknownNameError, match="tripod"):
        registry.robot("tripd", host)
    result = invoke("list", "modls")
    assert result.exit_code != 0 and "did you mean models" in result.output
    result = invoke("plugin")
    assert result.exit_code != 0 and "did you mean plugins" in result.output


def test_plugins_command_lists_hooks(host):
    host.register(ToyPlugin(), "toy", distribution="toy-dist", version="1.2")
    described = json.loads(invoke("plugins").stdout)
    (toy,) = described["plugins"]
    assert toy["name"] == "toy" and toy["version"] == "1.2" and toy["builtin"] is False
    assert toy["hooks"] == ["symbench_commands", "symbench_evaluators", "symbench_models",
                            "symbench_robots", "symbench_splits"]

"""The plugin system: every hook, in-process registration, broken plugins, restriction,
and the guards: no name silently replaced, every failure reported, no misspelt plugin."""

from __future__ import annotations

import json
from dataclasses import dataclass
from importlib.metadata import EntryPoint, entry_points
from pathlib import Path
from types import SimpleNamespace
from typing import Any

import click
import pytest
from cli_invoke import error_line
from click.testing import CliRunner

from symbench import __version__, hookimpl
from symbench.core.cli import build_cli, main
from symbench.core.common.errors import SymbenchError, UnknownNameError
from symbench.core.plugin import host as plugins
from symbench.core.plugin import registry
from symbench.core.plugin.entries import EvaluatorEntry, ModelEntry, RobotEntry, SplitEntry
from symbench.core.plugin.host import PluginHost, set_host

GHOST = EntryPoint("ghost", "symbench_no_such_module_xyz", "symbench")
GHOST_WARNING = (
    "warning: plugin 'ghost' failed to import: ModuleNotFoundError: "
    "No module named 'symbench_no_such_module_xyz'"
)


class ToyPlugin:
    """One implementation of every hook, as a third party would write it."""

    @hookimpl
    def symbench_models(self):
        return [
            ModelEntry("toy", "torch", "leg_grouped", "acc", True, build=lambda dims: None),
            ModelEntry("toy", "jax", "leg_grouped", "acc", True, build=lambda dims: None),
        ]

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


class EvilSdnn:
    """A third party's model under a built-in's name."""

    @hookimpl
    def symbench_models(self):
        return [ModelEntry("sdnn", "torch", "leg_grouped", "acc", True, build=lambda dims: None)]


class Publisher:
    """A third party's command under a core command's name."""

    @hookimpl
    def symbench_commands(self, cli: click.Group):
        @cli.command("publish")
        def publish():
            """Accept every record."""


@dataclass
class FakeEntryPoint:
    """An installed entry point of a distribution of our choosing."""

    name: str
    plugin: Any
    distribution: str
    version: str = "6.6.6"

    @property
    def dist(self) -> SimpleNamespace:
        return SimpleNamespace(metadata={"Name": self.distribution}, version=self.version)

    def load(self) -> Any:
        return self.plugin


def installed_and(monkeypatch, *extra) -> None:
    """The entry points really installed, plus `extra`."""
    real = entry_points(group="symbench")
    monkeypatch.setattr(plugins, "entry_points", lambda group: [*real, *extra])


def lines(text: str) -> list[str]:
    return [line for line in text.splitlines() if line]


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
    # a terminal wide enough for the table (narrower ones get one block per entry)
    table = CliRunner().invoke(build_cli(), ["list", "models"], env={"COLUMNS": "200"})
    assert table.exit_code == 0, table.output
    rows = [[c.strip() for c in line.split("│")[1:-1]] for line in lines(table.stdout)]
    assert [row[:2] for row in rows if row] == [["toy", "jax"], ["toy", "torch"]]


def test_symbench_commands_hook_adds_a_command(host):
    host.register(ToyPlugin(), "toy")
    listed = invoke("--help").stdout.split("\nCommands:\n", 1)[1]
    assert "toy-hello" in [line.split()[0] for line in lines(listed)]
    assert invoke("toy-hello").stdout.strip() == "hello from toy"


def test_broken_plugin_is_named_and_others_keep_working(host):
    host.register(ToyPlugin(), "toy")
    host.register(BrokenPlugin(), "broken-robots")
    result = invoke("list", "robots", "--json")
    assert result.exit_code == 0
    assert [r["name"] for r in json.loads(result.stdout)] == ["tripod"]
    problem, unshipped = sorted(lines(result.stderr))
    assert problem == (
        "warning: plugin 'broken-robots' failed in symbench_robots: "
        "RuntimeError: spec folder vanished"
    )
    assert unshipped.startswith("warning: robot 'tripod' of plugin 'toy'")  # has no folder
    described = json.loads(invoke("plugins").stdout)
    assert {
        "plugin": "broken-robots",
        "where": "symbench_robots",
        "error": "RuntimeError: spec folder vanished",
    } in described["problems"]
    assert invoke("list", "models", "--json").exit_code == 0


def test_plugin_that_fails_to_import_is_named(monkeypatch):
    broken = EntryPoint("ghost", "symbench_no_such_module_xyz", "symbench")
    monkeypatch.setattr(plugins, "entry_points", lambda group: [broken])
    h = PluginHost()
    h.load_entry_points(allowed="all")
    assert [p.plugin for p in h.problems] == ["ghost"]
    error = "ModuleNotFoundError: No module named 'symbench_no_such_module_xyz'"
    assert (h.problems[0].where, h.problems[0].error) == ("import", error)


@pytest.mark.parametrize(
    "allowed,loaded",
    [("all", True), ("none", False), ("", False), ("other,tester", True), ("other", False)],
)
def test_environment_variable_restricts_third_party(monkeypatch, allowed, loaded):
    eps = [
        EntryPoint("tester", "symbench.core.common.errors", "symbench"),
        EntryPoint("other", "symbench.core.plugin.entries", "symbench"),
    ]
    monkeypatch.setattr(plugins, "entry_points", lambda group: eps)
    monkeypatch.setenv(plugins.ENV_VAR, allowed)
    h = PluginHost()
    h.load_entry_points()
    assert ("tester" in h.info) is loaded


def test_wrong_type_is_a_problem_of_the_plugin(host):
    class Wrong:
        @hookimpl
        def symbench_splits(self):
            return [SplitEntry("other-split", assign=lambda s, seed: None), "not an entry"]

    host.register(ToyPlugin(), "toy")
    host.register(Wrong(), "wrong")
    assert list(registry.collect("splits", host)) == ["other-split", "toy-split"]
    assert [str(p) for p in host.problems] == [
        "plugin 'wrong' failed in symbench_splits: returned str, expected SplitEntry"
    ]


def test_unknown_names_get_the_closest(host):
    host.register(ToyPlugin(), "toy")
    with pytest.raises(UnknownNameError, match="did you mean toy"):
        registry.model("tay", "torch", host)
    with pytest.raises(SymbenchError, match="no 'flax' backend"):
        registry.model("toy", "flax", host)
    with pytest.raises(UnknownNameError, match="tripod"):
        registry.robot("tripd", host)
    assert error_line(invoke("list", "modls"), 1) == (
        "Error: unknown list kind 'modls'; did you mean models? "
        "(known: datasets, evaluators, models, robots, splits)"
    )
    message = error_line(invoke("plugin"), 2)
    assert message.startswith("Error: unknown command 'plugin'; did you mean plugins? (known: ")
    assert "toy-hello" in message.removesuffix(")").split(", ")  # a plugin's command too


def test_plugins_command_lists_hooks(host):
    host.register(ToyPlugin(), "toy", distribution="toy-dist", version="1.2")
    described = json.loads(invoke("plugins").stdout)
    (toy,) = described["plugins"]
    assert toy["name"] == "toy" and toy["version"] == "1.2" and toy["builtin"] is False
    assert toy["hooks"] == [
        "symbench_commands",
        "symbench_evaluators",
        "symbench_models",
        "symbench_robots",
        "symbench_splits",
    ]


# Guard 1: a name registered twice is an error naming both distributions, built-ins included.


@pytest.mark.parametrize("entry_point", ["aaa_models", "zzz_models"])  # sorts before / after
def test_a_builtin_model_name_taken_by_another_distribution_is_an_error(monkeypatch, entry_point):
    installed_and(monkeypatch, FakeEntryPoint(entry_point, EvilSdnn(), "evil-dist"))
    h = PluginHost()
    h.load_entry_points("all")
    set_host(h)
    try:
        result = CliRunner().invoke(build_cli(), ["run", "--model", "sdnn", "--robot", "hexa"])
    finally:
        set_host(None)
    builtin = f"plugin 'torch_models' (symbench {__version__})"
    evil = f"plugin '{entry_point}' (evil-dist 6.6.6)"
    first, second = (evil, builtin) if entry_point < "torch_models" else (builtin, evil)
    assert result.exit_code == 1
    assert lines(result.stderr) == [
        f"Error: model 'sdnn/torch' is registered twice: by {first} and by {second}; "
        "uninstall one or leave it out of SYMBENCH_PLUGINS"
    ]


def test_an_entry_point_name_declared_by_two_distributions_is_an_error(monkeypatch):
    installed_and(monkeypatch, FakeEntryPoint("torch_models", EvilSdnn(), "evil-dist"))
    with pytest.raises(SymbenchError) as error:
        PluginHost().load_entry_points("all")
    assert str(error.value) == (
        f"plugin entry point 'torch_models' is registered twice: by plugin 'torch_models' "
        f"(symbench {__version__}) and by plugin 'torch_models' (evil-dist 6.6.6); "
        "uninstall one or leave it out of SYMBENCH_PLUGINS"
    )


def test_a_core_command_name_taken_by_a_plugin_is_an_error(host):
    host.register(Publisher(), "publisher", distribution="evil-dist", version="6.6.6")
    with pytest.raises(SymbenchError) as error:
        build_cli()
    assert str(error.value) == (
        f"command 'publish' is registered twice: by symbench {__version__} (core) and by "
        "plugin 'publisher' (evil-dist 6.6.6); uninstall one or leave it out of SYMBENCH_PLUGINS"
    )


def test_a_plugin_command_name_taken_by_another_plugin_is_an_error(host):
    host.register(ToyPlugin(), "toy", distribution="toy-dist", version="1.2")
    host.register(ToyPlugin(), "copycat")
    with pytest.raises(SymbenchError) as error:
        build_cli()
    assert str(error.value) == (
        "command 'toy-hello' is registered twice: by plugin 'toy' (toy-dist 1.2) and by "
        "plugin 'copycat' (in-process); uninstall one or leave it out of SYMBENCH_PLUGINS"
    )


# Guard 2: `symbench plugins` lists every registered name with its distribution and version.


def test_plugins_command_lists_every_name_with_its_distribution():
    set_host(None)  # the installed plugins: symbench's built-ins and the example plugin
    described = json.loads(invoke("plugins").stdout)
    listed = {
        (n["kind"], n["name"]): (n["plugin"], n["distribution"], n["version"])
        for n in described["names"]
    }
    assert listed[("model", "sdnn/torch")] == ("torch_models", "symbench", __version__)
    assert listed[("model", "sdnn/jax")] == ("jax_models", "symbench", __version__)
    assert listed[("model", "leg-attention/torch")] == (
        "example_models",
        "symbench-example-plugin",
        "0.1.0",
    )
    assert listed[("robot", "hexa")] == ("robots", "symbench", __version__)
    registered = {(kind[:-1], key) for kind in registry.KINDS for key in registry.collect(kind)}
    assert set(listed) == registered and len(described["names"]) == len(registered)


def test_plugins_command_lists_plugin_commands(host):
    host.register(ToyPlugin(), "toy", distribution="toy-dist", version="1.2")
    names = json.loads(invoke("plugins").stdout)["names"]
    assert {
        "kind": "command",
        "name": "toy-hello",
        "plugin": "toy",
        "distribution": "toy-dist",
        "version": "1.2",
    } in names
    assert {
        "kind": "model",
        "name": "toy/jax",
        "plugin": "toy",
        "distribution": "toy-dist",
        "version": "1.2",
    } in names


# Guard 3: a plugin that fails to import is reported by every command, one line each, and a
# name it may have provided says so.


def test_every_command_reports_a_plugin_that_failed_to_import(monkeypatch):
    installed_and(monkeypatch, GHOST)
    h = PluginHost()
    h.load_entry_points("all")
    set_host(h)
    try:
        cli = build_cli()
        commands = cli.list_commands(click.Context(cli))
        results = {name: CliRunner().invoke(cli, [name, "--help"]) for name in commands}
        listing = CliRunner().invoke(cli, ["list", "robots", "--json"])
    finally:
        set_host(None)
    assert {"run", "data", "publish", "plugins", "list"} <= set(results)
    for name, result in results.items():
        assert result.exit_code == 0 and lines(result.stderr) == [GHOST_WARNING], name
    assert listing.exit_code == 0 and lines(listing.stderr) == [GHOST_WARNING]
    assert "hexa" in {r["name"] for r in json.loads(listing.stdout)}


def test_run_names_the_plugin_that_failed_for_an_unknown_model(monkeypatch):
    monkeypatch.setattr(plugins, "entry_points", lambda group: [GHOST])
    h = PluginHost()
    h.load_entry_points("all")
    h.register(ToyPlugin(), "toy")
    set_host(h)
    try:
        result = CliRunner().invoke(
            build_cli(), ["run", "--model", "ghost-net", "--robot", "tripod"]
        )
    finally:
        set_host(None)
    assert result.exit_code == 1
    assert lines(result.stderr) == [
        GHOST_WARNING,
        "Error: unknown model 'ghost-net' (known: toy); it may be lost with what failed: plugin "
        "'ghost' failed to import: ModuleNotFoundError: No module named "
        "'symbench_no_such_module_xyz'",
    ]


# Guard 4: a name in SYMBENCH_PLUGINS that is not installed is an error.


def test_unknown_name_in_symbench_plugins_is_an_error(monkeypatch, capsys):
    eps = [
        EntryPoint("tester", "symbench.core.common.errors", "symbench"),
        EntryPoint("example_models", "symbench.core.plugin.entries", "symbench"),
    ]
    monkeypatch.setattr(plugins, "entry_points", lambda group: eps)
    monkeypatch.setenv(plugins.ENV_VAR, "tester, exmple_models")
    monkeypatch.setattr("sys.argv", ["symbench", "list", "models"])
    set_host(None)
    with pytest.raises(SystemExit) as exit_:
        main()
    assert exit_.value.code == 1
    assert lines(capsys.readouterr().err) == [
        "error: SYMBENCH_PLUGINS: unknown plugin 'exmple_models'; did you mean example_models? "
        "(known: example_models, tester)"
    ]
    with pytest.raises(SymbenchError):  # no half-loaded host was left behind
        plugins.get_host()

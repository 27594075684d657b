"""The installed `symbench` console script works end to end.

Run with SYMBENCH_PLUGINS=none, so that only the built-in plugins load and every output is
known exactly, whatever else is installed in the environment."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from symbench import __version__
from symbench.core.cli import LAZY_COMMANDS, LIST_KINDS, cli
from symbench.core.plugin.entries import describe
from symbench.core.plugin.host import PluginHost
from symbench.core.plugin.registry import collect, names

SYMBENCH = shutil.which("symbench", path=str(Path(sys.executable).parent)) or "symbench"
CORE_COMMANDS = sorted({*cli.commands, *LAZY_COMMANDS})
BUILTIN_PLUGINS = {  # entry point -> its hooks
    "evaluators": ["symbench_evaluators"],
    "jax_models": ["symbench_models"],
    "robots": ["symbench_robots"],
    "splits": ["symbench_splits"],
    "torch_models": ["symbench_models"],
}
BUILTIN_MODELS = {
    f"{name}/{backend}"
    for name in ("ffnn", "ffnn-leg", "gnn", "sdgnn", "sdnn")
    for backend in ("torch", "jax")
}


def run(*args: str) -> subprocess.CompletedProcess:
    env = dict(os.environ, SYMBENCH_PLUGINS="none")
    return subprocess.run([SYMBENCH, *args], capture_output=True, text=True, timeout=120, env=env)


@pytest.fixture(scope="module")
def builtins() -> PluginHost:
    """A host of the built-in plugins, loaded in this process as the console script loads it."""
    host = PluginHost()
    host.load_entry_points("none")
    return host


def test_help_lists_core_commands():
    result = run("--help")
    assert result.returncode == 0, result.stderr
    listed = result.stdout.split("\nCommands:\n", 1)[1].splitlines()
    assert [line.split()[0] for line in listed if line.strip()] == CORE_COMMANDS
    assert {"list", "plugins", "run", "bench", "data", "sim"} <= set(CORE_COMMANDS)


def test_plugins_and_list_give_json(builtins):
    result = run("plugins")
    assert result.returncode == 0, result.stderr
    described = json.loads(result.stdout)
    assert described["plugins"] == [
        {
            "name": name,
            "distribution": "symbench",
            "version": __version__,
            "builtin": True,
            "hooks": hooks,
        }
        for name, hooks in sorted(BUILTIN_PLUGINS.items())
    ]
    assert described["problems"] == []
    assert described["names"] == names(builtins)
    by_kind = {
        kind: {row["name"] for row in described["names"] if row["kind"] == kind}
        for kind in ("model", "robot", "split")
    }
    assert by_kind["model"] == BUILTIN_MODELS
    assert by_kind["robot"] == {"magneto", "hexa", "nona"}
    assert {"iid", "unseen-heading", "unseen-rotation"} <= by_kind["split"]

    result = run("list", "models", "--json")
    assert result.returncode == 0, result.stderr
    models = json.loads(result.stdout)
    assert models == [describe(entry) for entry in collect("models", builtins).values()]
    assert {f"{row['name']}/{row['backend']}" for row in models} == BUILTIN_MODELS
    sdnn = next(row for row in models if row["name"] == "sdnn")
    assert (sdnn["view"], sdnn["equivariant"]) == ("leg_grouped", True)


@pytest.mark.parametrize(
    "args,status,message",
    [
        (
            ("lst",),
            2,
            f"Error: unknown command 'lst'; did you mean list? (known: {', '.join(CORE_COMMANDS)})",
        ),
        (
            ("list", "robts"),
            1,
            f"Error: unknown list kind 'robts'; did you mean robots? "
            f"(known: {', '.join(sorted(LIST_KINDS))})",
        ),
    ],
)
def test_unknown_names_are_clear_errors(args, status, message):
    result = run(*args)
    assert (result.returncode, result.stdout, result.stderr) == (status, "", message + "\n")

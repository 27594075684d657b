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


def test_python_dash_m_symbench_is_the_same_command():
    env = dict(os.environ, SYMBENCH_PLUGINS="none")
    module = [sys.executable, "-m", "symbench"]
    for args in (["--help"], ["--version"]):
        result = subprocess.run([*module, *args], capture_output=True, text=True, env=env)
        assert result.returncode == 0, result.stderr
        assert result.stdout == run(*args).stdout  # prog name `symbench`, not `__main__.py`
    assert result.stdout.startswith("symbench, version ")
    result = subprocess.run([*module, "list", "--bogus"], capture_output=True, text=True, env=env)
    assert result.returncode == 2 and "Usage: symbench list" in result.stderr


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


# --- a closed standard output, narrow terminals ------------------------------------------


def closed_pipe_run(*args: str) -> subprocess.CompletedProcess:
    """`symbench ARGS` writing into a pipe whose reader has already gone (`| head` done)."""
    read, write = os.pipe()
    os.close(read)
    try:
        env = dict(os.environ, SYMBENCH_PLUGINS="none")
        return subprocess.run(
            [SYMBENCH, *args], stdout=write, stderr=subprocess.PIPE, text=True, env=env
        )
    finally:
        os.close(write)


@pytest.mark.parametrize(
    "args",
    [
        ("list", "models"),  # a rich table
        ("list", "robots", "--json"),  # click.echo
        ("--help",),  # outside a command
        ("sim", "check", "--robot", "magneto", "--seconds", "0.02"),
        ("sim", "check", "--robot", "magneto", "--seconds", "0.02", "--json"),
    ],
)
def test_a_closed_stdout_exits_141_without_a_message(args):
    """Status 141 (128 + SIGPIPE, as for any program writing into a closed pipe): not 1,
    the status of a failure or of a detached robot, and no traceback or error line."""
    result = closed_pipe_run(*args)
    assert (result.returncode, result.stderr) == (141, "")


def test_the_closed_stdout_check_can_fail():
    """A command that fails for another reason still says so, with status 1."""
    result = closed_pipe_run("sim", "check", "--robot", "hexx")
    assert result.returncode == 1 and "unknown robot 'hexx'" in result.stderr


def run_at_width(columns: int, *args: str) -> subprocess.CompletedProcess:
    env = dict(os.environ, SYMBENCH_PLUGINS="none", COLUMNS=str(columns))
    return subprocess.run([SYMBENCH, *args], capture_output=True, text=True, timeout=120, env=env)


@pytest.mark.parametrize("kind", ["models", "robots", "evaluators", "splits"])
def test_list_tables_fit_a_narrow_terminal(kind):
    """At 40 columns every line fits, and every name and every word of every description
    is there in full (folded onto lines, never cut off with an ellipsis)."""
    result = run_at_width(40, "list", kind)
    lines = result.stdout.splitlines()
    assert max(len(line) for line in lines) <= 40, result.stdout
    assert "…" not in result.stdout
    cells = " ".join(
        part.strip() for line in lines for part in line.split("│")[1:-1] if part.strip()
    )
    for entry in json.loads(run("list", kind, "--json").stdout):
        assert entry["name"] in cells.split()
        for word in str(entry.get("description", "")).split():
            assert word in cells, (word, result.stdout)


def test_list_tables_keep_one_row_per_entry_when_they_fit():
    result = run_at_width(200, "list", "robots")
    rows = [line for line in result.stdout.splitlines() if line.startswith("│ ")]
    assert [r.split("│")[1].strip() for r in rows] == ["hexa", "magneto", "nona"]

"""The installed `symbench` console script works end to end."""

from __future__ import annotations

import json
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

SYMBENCH = shutil.which("symbench", path=str(Path(sys.executable).parent)) or "symbench"


def run(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run([SYMBENCH, *args], capture_output=True, text=True, timeout=120)


def test_help_lists_core_commands():
    result = run("--help")
    assert result.returncode == 0
    for command in ("list", "plugins", "run", "bench"):
        assert command in result.stdout


def test_plugins_and_list_give_json():
    described = json.loads(run("plugins").stdout)
    assert set(described) == {"plugins", "problems", "names"}
    assert described["problems"] == []
    assert all(p["builtin"] for p in described["plugins"] if p["distribution"] == "symbench")
    models = json.loads(run("list", "models", "--json").stdout)
    assert isinstance(models, list)


@pytest.mark.parametrize(
    "args,expected", [(("lst",), "did you mean list"), (("list", "robts"), "did you mean robots")]
)
def test_unknown_names_are_clear_errors(args, expected):
    result = run(*args)
    assert result.returncode != 0
    assert expected in result.stderr
    assert "Traceback" not in result.stderr

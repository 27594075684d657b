"""The wheel is complete: built from a copy of the source tree, it holds every module of
symbench/ and every file of the top-level robots/ (as symbench/plugins/robots/specs/), and,
installed into a fresh virtual environment outside the repository, it lists and simulates the
built-in robots from there.

Nothing is downloaded, and nothing but the wheel supplies symbench there (conftest.py).
"""

from __future__ import annotations

import json
import sys
import tarfile
import zipfile
from pathlib import Path

import pytest
from fresh_env import ROOT, FreshEnv, files_under, run

ROBOTS = ROOT / "robots"
SPECS_IN_WHEEL = "symbench/plugins/robots/specs"
BUILT_IN = ["hexa", "magneto", "nona"]


class Installed(FreshEnv):
    """symbench's wheel and sdist, and a fresh virtual environment with the wheel installed."""

    def __init__(self, tmp: Path, source: Path, wheel: Path) -> None:
        self.wheel = wheel
        sdist = "from setuptools import build_meta; print(build_meta.build_sdist('../dist'))"
        run([sys.executable, "-c", sdist], source)
        (self.sdist,) = wheel.parent.glob("symbench-*.tar.gz")
        super().__init__(tmp, [wheel])


@pytest.fixture(scope="module")
def installed(tmp_path_factory, symbench_wheel) -> Installed:
    return Installed(tmp_path_factory.mktemp("wheel"), *symbench_wheel)


def test_the_wheel_holds_every_module_and_every_robot_file(installed):
    names = set(zipfile.ZipFile(installed.wheel).namelist())
    robot_files = files_under(ROBOTS)
    assert {f"{r}/robot.toml" for r in BUILT_IN} <= set(robot_files)
    missing = [f for f in robot_files if f"{SPECS_IN_WHEEL}/{f}" not in names]
    assert not missing, f"robots/ files missing from the wheel: {missing}"
    modules = [
        f"symbench/{f}" for f in files_under(ROOT / "symbench") if f.endswith((".py", ".pyi"))
    ]
    missing = [m for m in modules if m not in names]
    assert not missing, f"missing from the wheel (list the package in pyproject.toml): {missing}"
    assert "symbench/plugins/tuned_rates.toml" in names  # the zoo's per-robot learning rates


def test_the_sdist_holds_every_robot_file(installed):
    """`python -m build` makes the wheel from the sdist, so robots/ must be in it too."""
    with tarfile.open(installed.sdist) as sdist:
        names = {name.split("/", 1)[1] for name in sdist.getnames() if "/" in name}
    missing = [f for f in files_under(ROBOTS) if f"robots/{f}" not in names]
    assert not missing, f"robots/ files missing from the sdist: {missing}"


def test_symbench_runs_from_the_fresh_environment(installed):
    code = "import symbench, symbench.plugins.robots as r; print(symbench.__file__, r.ROBOTS_DIR)"
    result = run([installed.python, "-c", code], installed.tmp, installed.env)
    module, robots_dir = (Path(p).resolve() for p in result.stdout.split())
    assert module.is_relative_to(installed.site.resolve()), module
    assert robots_dir == (installed.site / SPECS_IN_WHEEL).resolve()


def test_the_installed_wheel_lists_the_built_in_robots(installed):
    listed = json.loads(installed.symbench("list", "robots", "--json").stdout)
    assert [r["name"] for r in listed] == BUILT_IN
    for robot in listed:
        spec_dir = Path(robot["spec_dir"])
        assert spec_dir == installed.site / SPECS_IN_WHEEL / robot["name"]
        assert files_under(spec_dir) == files_under(ROBOTS / robot["name"])


@pytest.mark.slow  # minutes on 2 cores: kept out of the default suite's 10
@pytest.mark.parametrize("robot", BUILT_IN)
def test_the_installed_wheel_simulates(installed, robot):
    """Builds the robot's MuJoCo model from the installed spec and steps the controller."""
    result = installed.symbench("sim", "check", "--robot", robot, "--seconds", "0.02", "--json")
    report = json.loads(result.stdout)
    assert report["scenario"]["robot"] == robot
    assert report["attached"] and report["sim_seconds"] > 0

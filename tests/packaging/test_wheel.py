"""The wheel is complete: built from a copy of the source tree, it holds every module of
symbench/ and every file of the top-level robots/ (as symbench/plugins/robots/specs/), and,
installed into a fresh virtual environment outside the repository, it lists and simulates the
built-in robots from there.

Nothing is downloaded: the wheel is built with `--no-build-isolation` (the setuptools of this
environment) and installed with `--no-deps`; the fresh environment sees this environment's
third-party packages through a folder of links to them that leaves out every symbench
distribution, so no editable finder can supply a file that the wheel lacks.
"""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
import sysconfig
import tarfile
import venv
import zipfile
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
ROBOTS = ROOT / "robots"
SPECS_IN_WHEEL = "symbench/plugins/robots/specs"
BUILT_IN = ["hexa", "magneto", "nona"]


def skip(folder: str, names: list[str]) -> set[str]:
    """What a build never reads: caches, environments, outputs (a stale build/ hides omissions)."""
    skipped = shutil.ignore_patterns(".*", "__pycache__", "*.egg-info")(folder, names)
    if Path(folder) == ROOT:
        skipped |= {"build", "dist", "runs", "results"} & set(names)
    return skipped


def files_under(folder: Path) -> list[str]:
    return sorted(
        p.relative_to(folder).as_posix()
        for p in folder.rglob("*")
        if p.is_file() and "__pycache__" not in p.parts
    )


def run(args: list, cwd: Path, env: dict | None = None) -> subprocess.CompletedProcess:
    result = subprocess.run(
        [str(a) for a in args], cwd=cwd, env=env, capture_output=True, text=True, timeout=300
    )
    assert result.returncode == 0, f"{args}\n{result.stdout}\n{result.stderr}"
    return result


class Installed:
    """The wheel, the sdist and a fresh virtual environment with the wheel installed."""

    def __init__(self, tmp: Path) -> None:
        self.tmp = tmp
        source = tmp / "source"
        shutil.copytree(ROOT, source, ignore=skip)
        dist = tmp / "dist"
        no_network = ["--no-index", "--no-deps", "--disable-pip-version-check"]
        pip = [sys.executable, "-m", "pip"]
        run([*pip, "wheel", "-q", *no_network, "--no-build-isolation", "-w", dist, source], tmp)
        (self.wheel,) = dist.glob("symbench-*.whl")
        sdist = "from setuptools import build_meta; print(build_meta.build_sdist('../dist'))"
        run([sys.executable, "-c", sdist], source)
        (self.sdist,) = dist.glob("symbench-*.tar.gz")

        self.venv = tmp / "fresh-venv"
        venv.EnvBuilder(with_pip=False).create(self.venv)
        self.python = self.venv / "bin" / "python"
        run([*pip, "--python", self.python, "install", "-q", *no_network, self.wheel], tmp)
        self.site = Path(
            run(
                [self.python, "-c", "import sysconfig; print(sysconfig.get_path('purelib'))"], tmp
            ).stdout.strip()
        )
        # This environment's third-party packages, without symbench and its editable finders;
        # addsitedir runs their .pth files (cmeel puts proxsuite on sys.path with one).
        deps = tmp / "deps"
        deps.mkdir()
        for entry in Path(sysconfig.get_path("purelib")).iterdir():
            if not entry.name.lower().startswith(("symbench", "__editable__")):
                (deps / entry.name).symlink_to(entry)
        (self.site / "_symbench_test_deps.pth").write_text(
            f"import site; site.addsitedir({str(deps)!r})\n"
        )
        self.env = {
            k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "SYMBENCH_PLUGINS")
        } | {"MUJOCO_GL": "disable", "PYTHONNOUSERSITE": "1", "SYMBENCH_HOME": str(tmp / "home")}

    def symbench(self, *args: str) -> subprocess.CompletedProcess:
        """The installed `symbench` command, run outside the repository."""
        return run([self.venv / "bin" / "symbench", *args], self.tmp, self.env)


@pytest.fixture(scope="module")
def installed(tmp_path_factory) -> Installed:
    return Installed(tmp_path_factory.mktemp("wheel"))


def test_the_wheel_holds_every_module_and_every_robot_file(installed):
    names = set(zipfile.ZipFile(installed.wheel).namelist())
    robot_files = files_under(ROBOTS)
    assert {f"{r}/robot.toml" for r in BUILT_IN} <= set(robot_files)
    missing = [f for f in robot_files if f"{SPECS_IN_WHEEL}/{f}" not in names]
    assert not missing, f"robots/ files missing from the wheel: {missing}"
    modules = [f"symbench/{f}" for f in files_under(ROOT / "symbench") if f.endswith(".py")]
    missing = [m for m in modules if m not in names]
    assert not missing, f"missing from the wheel (list the package in pyproject.toml): {missing}"


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


@pytest.mark.parametrize("robot", BUILT_IN)
def test_the_installed_wheel_simulates(installed, robot):
    """Builds the robot's MuJoCo model from the installed spec and steps the controller."""
    result = installed.symbench("sim", "check", "--robot", robot, "--seconds", "0.02", "--json")
    report = json.loads(result.stdout)
    assert report["scenario"]["robot"] == robot
    assert report["attached"] and report["sim_seconds"] > 0

"""Building wheels offline and installing them into a fresh virtual environment outside the
repository, shared by the packaging tests (symbench's own wheel, the example plugins').

Nothing is downloaded: wheels are built with `--no-build-isolation` (the setuptools of this
environment) and installed with `--no-deps`; the fresh environment sees this environment's
third-party packages through a folder of links to them that leaves out every symbench
distribution, so no editable finder can supply a file that a wheel lacks.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import sysconfig
import venv
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
NO_NETWORK = ["--no-index", "--no-deps", "--disable-pip-version-check"]
PIP = [sys.executable, "-m", "pip"]


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


def run(
    args: list, cwd: Path, env: dict | None = None, timeout: float = 300
) -> subprocess.CompletedProcess:
    result = subprocess.run(
        [str(a) for a in args], cwd=cwd, env=env, capture_output=True, text=True, timeout=timeout
    )
    assert result.returncode == 0, f"{args}\n{result.stdout}\n{result.stderr}"
    return result


def build_wheel(project: Path, tmp: Path, name: str) -> tuple[Path, Path]:
    """(the copy of `project` that was built, its wheel), built offline and not editable from
    a clean copy (the build writes build/ and *.egg-info next to the sources)."""
    source = tmp / f"source-{name}"
    shutil.copytree(project, source, ignore=skip)
    dist = tmp / "dist"
    run([*PIP, "wheel", "-q", *NO_NETWORK, "--no-build-isolation", "-w", dist, source], tmp)
    (wheel,) = dist.glob(f"{name.replace('-', '_')}-*.whl")
    return source, wheel


class FreshEnv:
    """A fresh virtual environment outside the repository with `wheels` installed."""

    def __init__(self, tmp: Path, wheels: list[Path]) -> None:
        self.tmp = tmp
        self.venv = tmp / "fresh-venv"
        venv.EnvBuilder(with_pip=False).create(self.venv)
        self.python = self.venv / "bin" / "python"
        run([*PIP, "--python", self.python, "install", "-q", *NO_NETWORK, *wheels], tmp)
        code = "import sysconfig; print(sysconfig.get_path('purelib'))"
        self.site = Path(run([self.python, "-c", code], tmp).stdout.strip())
        # This environment's third-party packages, without symbench and its editable finders;
        # addsitedir runs their .pth files (some packages put themselves on sys.path so).
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

    def symbench(self, *args: str, timeout: float = 300) -> subprocess.CompletedProcess:
        """The installed `symbench` command, run outside the repository."""
        return run([self.venv / "bin" / "symbench", *args], self.tmp, self.env, timeout)

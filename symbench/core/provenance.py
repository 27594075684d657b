"""Where a result came from: hardware, library versions, symbench version, git commit."""

from __future__ import annotations

import os
import platform
import subprocess
from collections.abc import Sequence
from importlib.metadata import PackageNotFoundError, version
from pathlib import Path

from symbench import __version__

LIBRARIES = ("numpy", "torch", "jax", "jaxlib", "flax", "optax", "mujoco", "dm-control",
             "proxsuite", "pandas", "pyarrow")


def package_versions(names: Sequence[str]) -> dict[str, str]:
    """Installed version of each named distribution ('not installed' when absent)."""
    out = {}
    for name in names:
        try:
            out[name] = version(name)
        except PackageNotFoundError:
            out[name] = "not installed"
    return out


def library_versions() -> dict[str, str]:
    """Python, symbench and every library a result depends on."""
    return {"python": platform.python_version(), "symbench": __version__,
            **package_versions(LIBRARIES)}


def hardware() -> dict[str, str | int | float]:
    memory_gib = 0.0
    meminfo = Path("/proc/meminfo")
    if meminfo.is_file():
        first = meminfo.read_text().split("\n", 1)[0].split()
        memory_gib = round(int(first[1]) / 2**20, 1)
    return {
        "cpu": _cpu_model(),
        "cores": os.cpu_count() or 0,
        "memory_gib": memory_gib,
        "machine": platform.machine(),
        "system": f"{platform.system()} {platform.release()}",
    }


def _cpu_model() -> str:
    cpuinfo = Path("/proc/cpuinfo")
    if cpuinfo.is_file():
        for line in cpuinfo.read_text().splitlines():
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    return platform.processor() or "unknown"


def git_commit() -> str:
    """The commit of the symbench source tree, with '+dirty' when it has local changes."""
    root = Path(__file__).resolve().parents[2]
    try:
        commit = subprocess.run(["git", "rev-parse", "HEAD"], cwd=root, capture_output=True,
                                text=True, timeout=10, check=True).stdout.strip()
        dirty = subprocess.run(["git", "status", "--porcelain", "--untracked-files=no"],
                               cwd=root, capture_output=True, text=True, timeout=10).stdout
    except (OSError, subprocess.SubprocessError):
        return "unknown"
    return commit + ("+dirty" if dirty.strip() else "")

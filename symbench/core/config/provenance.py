"""Where a result came from: hardware, library versions, git commit, and the model's code.

A record must let anyone re-run it: besides the environment it names the plugin that built
the network (distribution, version, a hash of its source files) and every hyper-parameter of
the build function, defaults included, so a later change of a default cannot go unnoticed.
"""

from __future__ import annotations

import hashlib
import importlib.util
import inspect
import os
import platform
import subprocess
from collections.abc import Sequence
from importlib.metadata import PackageNotFoundError, packages_distributions, version
from pathlib import Path
from typing import Any

from symbench.core.common.errors import SymbenchError
from symbench.core.common.hashing import sha256_file
from symbench.core.common.lazy import Lazy
from symbench.core.common.version import __version__
from symbench.core.plugin.entries import ModelEntry

LIBRARIES = (
    "numpy",
    "torch",
    "jax",
    "jaxlib",
    "flax",
    "optax",
    "mujoco",
    "dm-control",
    "numba",
    "daqp",
    "pandas",
    "pyarrow",
)


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
    return {
        "python": platform.python_version(),
        "symbench": __version__,
        **package_versions(LIBRARIES),
    }


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
    root = Path(__file__).resolve().parents[3]  # the repository root
    try:
        commit = subprocess.run(
            ["git", "rev-parse", "HEAD"],
            cwd=root,
            capture_output=True,
            text=True,
            timeout=10,
            check=True,
        ).stdout.strip()
        dirty = subprocess.run(
            ["git", "status", "--porcelain", "--untracked-files=no"],
            cwd=root,
            capture_output=True,
            text=True,
            timeout=10,
        ).stdout
    except (OSError, subprocess.SubprocessError):
        return "unknown"
    return commit + ("+dirty" if dirty.strip() else "")


def _build_function(entry: ModelEntry) -> Any:
    return entry.build.resolve() if isinstance(entry.build, Lazy) else entry.build


def _build_module(entry: ModelEntry) -> str:
    if isinstance(entry.build, Lazy):
        return entry.build.target.split(":")[0]
    return getattr(entry.build, "__module__", None) or "(unknown)"


def build_hyperparameters(entry: ModelEntry, hyper: dict[str, Any]) -> dict[str, Any]:
    """Every keyword the build function receives: its defaults updated by `hyper`."""
    signature = inspect.signature(_build_function(entry))
    defaults = {
        name: p.default
        for name, p in list(signature.parameters.items())[1:]
        if p.default is not inspect.Parameter.empty
    }
    return {**defaults, **hyper}


def source_files(module: str) -> tuple[Path, list[Path]]:
    """The plugin's source: the package folder holding `module` and its *.py files (the
    module's own folder and file for a top-level module)."""
    spec = importlib.util.find_spec(module)
    if spec is None or spec.origin is None or not spec.origin.endswith(".py"):
        raise SymbenchError(f"cannot find the source files of module '{module}'")
    origin = Path(spec.origin)
    if spec.submodule_search_locations is None and "." not in module:
        return origin.parent, [origin]
    return origin.parent, sorted(
        p for p in origin.parent.rglob("*.py") if "__pycache__" not in p.parts
    )


def files_sha256(root: Path, files: Sequence[Path]) -> str:
    """One SHA-256 over files: their names relative to `root` and their bytes."""

    digest = hashlib.sha256()
    for path in files:
        digest.update(f"{path.relative_to(root).as_posix()}\0{sha256_file(path)}\n".encode())
    return digest.hexdigest()


def distribution_of(module: str) -> tuple[str, str]:
    """(distribution, version) installed for the top-level package of `module`."""
    names = sorted(set(packages_distributions().get(module.split(".")[0], [])))
    if not names:
        return "(not installed)", ""
    return names[0], version(names[0])


def plugin_info(entry: ModelEntry) -> dict[str, str]:
    """Which code built the network: module, distribution, version, source hash."""
    module = _build_module(entry)
    distribution, dist_version = distribution_of(module)
    return {
        "module": module,
        "distribution": distribution,
        "version": dist_version,
        "source_sha256": files_sha256(*source_files(module)),
    }


def checkpoint_file_hashes(folder: Path) -> dict[str, str]:
    """File name -> SHA-256 for the files directly in `folder` (a saved checkpoint)."""

    files = sorted(p for p in Path(folder).iterdir() if p.is_file())
    if not files:
        raise SymbenchError(f"checkpoint folder {folder} holds no files")
    return {p.name: sha256_file(p) for p in files}

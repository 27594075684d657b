"""Where symbench keeps its files: `$SYMBENCH_HOME`, else the user's cache directory."""

from __future__ import annotations

import os
from pathlib import Path


def symbench_home() -> Path:
    env = os.environ.get("SYMBENCH_HOME")
    if env:
        return Path(env).expanduser()
    cache = os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache"
    return Path(cache) / "symbench"


def datasets_dir() -> Path:
    return symbench_home() / "datasets"


def dataset_ids() -> list[str]:
    """Ids of the datasets in the cache (a folder with a metadata.json each)."""
    root = datasets_dir()
    if not root.is_dir():
        return []
    return sorted(p.name for p in root.iterdir() if (p / "metadata.json").is_file())

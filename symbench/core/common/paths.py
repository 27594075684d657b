"""Where symbench keeps its files: `$SYMBENCH_HOME`, else the user's cache directory; and
whether a folder can take symbench's output, checked before any work is spent on it."""

from __future__ import annotations

import os
import tempfile
from pathlib import Path

from symbench.core.common.errors import SymbenchError


def symbench_home() -> Path:
    env = os.environ.get("SYMBENCH_HOME")
    if env:
        home = Path(env).expanduser()
    else:
        home = Path(os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache") / "symbench"
    blocker = next((p for p in (home, *home.parents) if p.exists()), None)
    if blocker is not None and not blocker.is_dir():
        raise SymbenchError(
            f"symbench's home {home} (SYMBENCH_HOME) cannot be a folder: {blocker} is a file"
        )
    return home


def datasets_dir() -> Path:
    return symbench_home() / "datasets"


def dataset_ids() -> list[str]:
    """Ids of the datasets in the cache (a folder with a metadata.json each; hidden folders
    are imports and replacements under way)."""
    root = datasets_dir()
    if not root.is_dir():
        return []
    return sorted(
        p.name
        for p in root.iterdir()
        if not p.name.startswith(".") and (p / "metadata.json").is_file()
    )


def unwritable_reason(folder: Path) -> str | None:
    """Why symbench cannot write files into `folder` (made when missing), or None when it
    can: tried by writing a scratch file, since permission bits do not tell (root, read-only
    mounts)."""
    try:
        folder.mkdir(parents=True, exist_ok=True)
        with tempfile.TemporaryFile(dir=folder):
            pass
    except (OSError, ValueError) as exc:  # ValueError: a NUL in the path
        return getattr(exc, "strerror", None) or str(exc)
    return None


def writable_folder(folder: Path, what: str) -> Path:
    """`folder`, made when missing, or an error naming `what` when nothing can be written there."""
    reason = unwritable_reason(Path(folder))
    if reason is not None:
        raise SymbenchError(f"{what} {folder}: cannot write there ({reason})")
    return Path(folder)

"""Atomic writes: a reader sees the old file (or folder) or the new one, never half of one.

Files get the permissions a plain `open` would give them (0666 less the umask): records,
datasets and boards are meant to be shared, which the 0600 of a `mkstemp` file prevented.
"""

from __future__ import annotations

import os
import secrets
import shutil
from pathlib import Path


def _hidden_sibling(path: Path, purpose: str) -> Path:
    """A fresh name beside `path`, hidden (leading dot) so that no listing takes it for data."""
    return path.with_name(f".{path.name}.{purpose}-{secrets.token_hex(6)}")


def write_bytes_atomic(path: Path, data: bytes) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    tmp = _hidden_sibling(path, "tmp")
    fd = os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o666)
    try:
        with os.fdopen(fd, "wb") as f:
            f.write(data)
            f.flush()
            os.fsync(f.fileno())
        os.replace(tmp, path)
    except BaseException:
        tmp.unlink(missing_ok=True)
        raise


def write_text_atomic(path: Path, text: str) -> None:
    write_bytes_atomic(path, text.encode())


def staging_folder(target: Path) -> Path:
    """A new empty folder beside `target` in which to build its replacement."""
    staging = _hidden_sibling(target, "staging")
    staging.mkdir(parents=True)
    return staging


def replace_folder(staging: Path, target: Path) -> None:
    """Put the complete folder `staging` at `target` by renames. The old `target` is set aside
    first and deleted only once `staging` has taken its place; should the second rename fail,
    it is put back, so nothing is lost before its replacement is complete."""
    old = _hidden_sibling(target, "old") if target.exists() else None
    if old is not None:
        os.replace(target, old)
    try:
        os.replace(staging, target)
    except BaseException:
        if old is not None:
            os.replace(old, target)
        raise
    if old is not None:
        shutil.rmtree(old, ignore_errors=True)

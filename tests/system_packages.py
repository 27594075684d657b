"""Debian packages some tests need (Chromium for the browser tests, OSMesa for rendering):
installed with apt-get when missing, one installation at a time (pytest-xdist's workers
each ask; the others wait), and a test fails, never skips, when that is not possible."""

from __future__ import annotations

import ctypes.util
import fcntl
import os
import shutil
import subprocess
import tempfile
from collections.abc import Callable
from pathlib import Path

import pytest


def ensure_package(package: str, present: Callable[[], bool], why: str) -> None:
    """Install the Debian `package` unless `present()`; fail naming `why` it is needed."""
    lock_path = Path(tempfile.gettempdir()) / f"symbench-{package}-install.lock"
    with open(lock_path, "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        if present():
            return
        environment = {**os.environ, "DEBIAN_FRONTEND": "noninteractive"}
        for command in (["apt-get", "update"], ["apt-get", "install", "-y", package]):
            try:
                done = subprocess.run(
                    command, capture_output=True, text=True, env=environment, timeout=1800
                )
            except OSError as exc:
                pytest.fail(f"cannot run `{' '.join(command)}` ({exc}): {why}")
            if done.returncode != 0:
                pytest.fail(
                    f"`{' '.join(command)}` failed (exit {done.returncode}): {why}\n"
                    + done.stderr[-2000:]
                )
    if not present():
        pytest.fail(f"apt-get installed {package}, but it is still missing: {why}")


def ensure_chromium() -> str:
    """The system's Chromium (Debian's `chromium`), for the browser tests."""
    ensure_package(
        "chromium",
        lambda: shutil.which("chromium") is not None,
        "the browser tests drive the Debian package chromium (root and package access)",
    )
    found = shutil.which("chromium")
    assert found is not None
    return found


def ensure_osmesa() -> None:
    """The OSMesa library MuJoCo renders with offscreen (MUJOCO_GL=osmesa)."""
    ensure_package(
        "libosmesa6",
        lambda: ctypes.util.find_library("OSMesa") is not None,
        "rendering climbs needs the Debian package libosmesa6 (root and package access)",
    )

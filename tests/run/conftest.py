"""A symbench home with the real smoke datasets of every robot, made once per session."""

from __future__ import annotations

import os

import pytest

ROBOTS = ("magneto", "hexa", "nona")


@pytest.fixture(scope="session")
def smoke_home(tmp_path_factory):
    from symbench.core.data.generation.generate import ensure_dataset

    home = tmp_path_factory.mktemp("symbench-home")
    before = os.environ.get("SYMBENCH_HOME")
    os.environ["SYMBENCH_HOME"] = str(home)
    for robot in ROBOTS:
        ensure_dataset(robot, "smoke", workers=1, show_progress=False)
    yield home
    if before is None:
        del os.environ["SYMBENCH_HOME"]
    else:
        os.environ["SYMBENCH_HOME"] = before

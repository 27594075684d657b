"""The packaging tests' shared fixture: symbench's wheel, built once per session (helpers in
fresh_env.py)."""

from __future__ import annotations

from pathlib import Path

import pytest
from fresh_env import ROOT, build_wheel


@pytest.fixture(scope="session")
def symbench_wheel(tmp_path_factory) -> tuple[Path, Path]:
    """(the copied source tree, symbench's wheel built from it): once per session."""
    return build_wheel(ROOT, tmp_path_factory.mktemp("symbench-wheel"), "symbench")

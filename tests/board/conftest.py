"""Fixtures of the site's tests: the records of site_records.py and the site built from
them."""

from __future__ import annotations

from pathlib import Path

import pytest
from site_records import write_results

from symbench.core.board.site import build_site


@pytest.fixture
def results(tmp_path: Path, make_record, as_schema_1) -> Path:
    """The records of site_records.py."""
    return write_results(tmp_path / "results", make_record, as_schema_1)


@pytest.fixture
def board(tmp_path: Path) -> Path:
    """Where the published board would be: empty unless a test publishes to it."""
    return tmp_path / "board"


@pytest.fixture
def site(results: Path, board: Path, tmp_path: Path) -> Path:
    """The site built from `results`."""
    out = tmp_path / "site"
    build_site(results, out, board)
    return out

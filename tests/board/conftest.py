"""Fixtures of the site's tests: the records of site_records.py and the site built from
them, made once per test module (a build takes 3-10 s; 25 tests read it). Both are shared:
a test that changes records, the board or the site works on `own_copy` of them."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from site_records import write_results

from symbench.core.board.site import build_site


@pytest.fixture(scope="module")
def results(tmp_path_factory, make_record, as_schema_1) -> Path:
    """The records of site_records.py (shared: read only)."""
    return write_results(tmp_path_factory.mktemp("records") / "results", make_record, as_schema_1)


@pytest.fixture(scope="module")
def board(tmp_path_factory) -> Path:
    """Where the published board would be: empty (shared: read only)."""
    return tmp_path_factory.mktemp("published") / "board"


@pytest.fixture(scope="module")
def site(results: Path, board: Path, tmp_path_factory) -> Path:
    """The site built from `results` (shared: read only; its pages name `results`' paths)."""
    out = tmp_path_factory.mktemp("built") / "site"
    build_site(results, out, board)
    return out


@pytest.fixture
def own_copy(tmp_path: Path):
    """`own_copy(folder)`: a private copy of a shared folder under this test's tmp_path, to
    change."""

    def copy(folder: Path) -> Path:
        return Path(shutil.copytree(folder, tmp_path / folder.name))

    return copy

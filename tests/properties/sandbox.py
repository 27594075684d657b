"""A fresh $SYMBENCH_HOME per Hypothesis example (function-scoped fixtures last a whole
test), and what a failed operation may leave there: nothing."""

from __future__ import annotations

import contextlib
import os
import tempfile
from collections.abc import Iterator
from pathlib import Path


@contextlib.contextmanager
def fresh_home() -> Iterator[Path]:
    """An empty symbench home for the block."""
    before = os.environ.get("SYMBENCH_HOME")
    with tempfile.TemporaryDirectory(prefix="symbench-home-") as home:
        os.environ["SYMBENCH_HOME"] = home
        try:
            yield Path(home)
        finally:
            if before is None:
                del os.environ["SYMBENCH_HOME"]
            else:
                os.environ["SYMBENCH_HOME"] = before


def files_under(folder: Path) -> list[str]:
    """Every file and folder under `folder`, hidden ones (temporary, staging) included."""
    return sorted(str(p.relative_to(folder)) for p in folder.rglob("*"))

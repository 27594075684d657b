"""A symbench home with the real smoke datasets of every robot, for the session."""

from __future__ import annotations

import pytest


@pytest.fixture(scope="session")
def smoke_home(real_smoke_copy):
    with real_smoke_copy("symbench-home") as home:
        yield home

"""Smoke data shared by the model tests."""

from __future__ import annotations

import pytest

from symbench.testing.synthetic import synthetic_views


@pytest.fixture(scope="session")
def smoke():
    """Training and validation data of a 4-legged robot in every view."""
    return synthetic_views(4, 1024, seed=0), synthetic_views(4, 256, seed=1)

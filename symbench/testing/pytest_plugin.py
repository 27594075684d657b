"""pytest plugin (entry point `pytest11`): the equivariance kit as fixtures.

    def test_my_model_is_equivariant(symbench_kit, symbench_groups):
        for group in symbench_groups.values():
            symbench_kit.assert_equivariant(my_entry, group)

`--symbench-samples N` sets the number of random inputs per group element. Importing this
module imports neither torch nor JAX.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import pytest

from symbench.core.plugin.entries import ModelEntry
from symbench.core.symmetry.groups import LegGroup


@dataclass(frozen=True)
class Kit:
    n_samples: int

    def check(self, entry: ModelEntry, group: LegGroup, **kwargs: Any):
        from symbench.testing.equivariance import check_model

        return check_model(entry, group, **{"n_samples": self.n_samples, **kwargs})

    def assert_equivariant(self, entry: ModelEntry, group: LegGroup, **kwargs: Any):
        from symbench.testing.equivariance import assert_equivariant

        return assert_equivariant(entry, group, **{"n_samples": self.n_samples, **kwargs})


def pytest_addoption(parser: pytest.Parser) -> None:
    parser.getgroup("symbench").addoption(
        "--symbench-samples",
        type=int,
        default=32,
        help="random inputs per group element in symbench's equivariance kit (default 32)",
    )


@pytest.fixture
def symbench_kit(request: pytest.FixtureRequest) -> Kit:
    """The equivariance kit with this session's sample count."""
    return Kit(request.config.getoption("--symbench-samples"))


@pytest.fixture(scope="session")
def symbench_groups() -> dict[str, LegGroup]:
    """The symmetry groups of the built-in robots, by robot name."""
    from symbench.testing.groups import BUILTIN_ROBOTS, robot_group

    return {name: robot_group(name) for name in BUILTIN_ROBOTS}

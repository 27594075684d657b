"""pytest plugin (entry point `pytest11`): the equivariance kit as fixtures.

    def test_my_model_is_equivariant(symbench_kit, symbench_groups):
        for group in symbench_groups.values():  # every registered robot, plugins' included
            symbench_kit.assert_equivariant(my_entry, group)

    def test_one_robot_at_a_time(symbench_kit, symbench_robot, symbench_group):
        symbench_kit.assert_equivariant(my_entry, symbench_group)  # one test per robot

`group` may be a `LegGroup` (checked on a regular robot with that many legs) or a registered
robot's name, e.g. `symbench_robot` (its own group and leg frames). `--symbench-samples N`
sets the number of raw states per group element of the `symbench_kit` fixture only; a
directly imported `assert_equivariant` keeps its own `n_samples` (default 32). Importing this
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

    def check(self, entry: ModelEntry, group: LegGroup | str, **kwargs: Any):
        from symbench.testing.equivariance import check_model

        return check_model(entry, group, **{"n_samples": self.n_samples, **kwargs})

    def assert_equivariant(self, entry: ModelEntry, group: LegGroup | str, **kwargs: Any):
        from symbench.testing.equivariance import assert_equivariant

        return assert_equivariant(entry, group, **{"n_samples": self.n_samples, **kwargs})

    def symmetry_group(self, entry: ModelEntry, group: LegGroup | str, **kwargs: Any):
        from symbench.testing.model_group import measure_symmetry_group

        return measure_symmetry_group(entry, group, **kwargs)


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
    """The symmetry groups of every registered robot (built-in and plugin), by robot name."""
    from symbench.testing.groups import robot_groups

    return robot_groups()


def pytest_generate_tests(metafunc: pytest.Metafunc) -> None:
    """A test that asks for `symbench_robot` runs once per registered robot (id: its name)."""
    if "symbench_robot" in metafunc.fixturenames:
        from symbench.testing.groups import registered_robots

        names = list(registered_robots())
        metafunc.parametrize("symbench_robot", names, ids=names, scope="session")


@pytest.fixture
def symbench_group(symbench_robot: str) -> LegGroup:
    """The symmetry group of this test's `symbench_robot`."""
    from symbench.testing.groups import robot_group

    return robot_group(symbench_robot)

"""symbench's test kit for plugin authors: exact equivariance checks and synthetic data.

    from symbench.testing import assert_equivariant, robot_group
    assert_equivariant(my_entry, robot_group("hexa"))

Also a pytest plugin (fixtures `symbench_kit`, `symbench_groups`, and `symbench_robot` /
`symbench_group`, one test per registered robot, plugins' included), registered through the
`pytest11` entry point, so any project with symbench installed can use it.
"""

from symbench.testing.equivariance import (
    TOLERANCES,
    EquivarianceReport,
    assert_equivariant,
    check_model,
    element_errors,
    relative_error,
)
from symbench.testing.groups import BUILTIN_ROBOTS, registered_robots, robot_group, robot_groups
from symbench.testing.synthetic import equivariant_target, synthetic_views

__all__ = [
    "BUILTIN_ROBOTS",
    "TOLERANCES",
    "EquivarianceReport",
    "assert_equivariant",
    "check_model",
    "element_errors",
    "equivariant_target",
    "registered_robots",
    "relative_error",
    "robot_group",
    "robot_groups",
    "synthetic_views",
]

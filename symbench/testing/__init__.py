"""symbench's test kit for plugin authors: exact equivariance checks and synthetic data.

    from symbench.testing import assert_equivariant, measure_symmetry_group
    assert_equivariant(my_entry, "hexa")  # raw states turned and relabelled, view recomputed
    measure_symmetry_group(my_entry, "hexa").verdict  # the leg permutations it respects

Also a pytest plugin (fixtures `symbench_kit`, `symbench_groups`, and `symbench_robot` /
`symbench_group`, one test per registered robot, plugins' included), registered through the
`pytest11` entry point, so any project with symbench installed can use it.
"""

from symbench.testing.equivariance import (
    TOLERANCES,
    ControlError,
    ControlPassedError,
    EquivarianceReport,
    assert_equivariant,
    check_model,
    control_transforms,
    element_errors,
    relative_error,
)
from symbench.testing.groups import (
    BUILTIN_ROBOTS,
    registered_robots,
    robot_geometry_group,
    robot_group,
    robot_groups,
)
from symbench.testing.model_group import SymmetryGroupReport, measure_symmetry_group
from symbench.testing.raw_states import (
    RawStates,
    regular_frames,
    robot_frames,
    synthetic_raw_states,
)
from symbench.testing.synthetic import equivariant_target, synthetic_views

__all__ = [
    "BUILTIN_ROBOTS",
    "TOLERANCES",
    "ControlError",
    "ControlPassedError",
    "EquivarianceReport",
    "RawStates",
    "SymmetryGroupReport",
    "assert_equivariant",
    "check_model",
    "control_transforms",
    "element_errors",
    "equivariant_target",
    "measure_symmetry_group",
    "registered_robots",
    "regular_frames",
    "relative_error",
    "robot_frames",
    "robot_geometry_group",
    "robot_group",
    "robot_groups",
    "synthetic_raw_states",
    "synthetic_views",
]

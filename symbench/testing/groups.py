"""The symmetry group of a registered robot, read from its spec."""

from __future__ import annotations

from symbench.core.symmetry.groups import LegGroup

BUILTIN_ROBOTS = ("magneto", "hexa", "nona")


def robot_group(name: str) -> LegGroup:
    from symbench.core.robot.specs import load_robot

    return load_robot(name).group

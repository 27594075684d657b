"""The symmetry groups of registered robots, read from their specs: the built-in ones and
every robot that an installed plugin registers."""

from __future__ import annotations

from symbench.core.symmetry.groups import LegGroup

BUILTIN_ROBOTS = ("magneto", "hexa", "nona")


def robot_group(name: str) -> LegGroup:
    """The group of the registered robot `name` (built-in or from a plugin)."""
    from symbench.core.robot.specs import load_robot

    return load_robot(name).group


def robot_geometry_group(name: str) -> LegGroup:
    """The geometry group of the registered robot `name`: its declared rotations and the
    mirrors its geometry has (check a model on it with `frames=robot_frames(name)`)."""
    from symbench.core.robot.specs import load_robot

    return load_robot(name).geometry_group


def registered_robots() -> tuple[str, ...]:
    """Every registered robot, built-in and plugin, sorted by name."""
    from symbench.core.plugin import registry

    return tuple(sorted(registry.collect("robots")))


def robot_groups() -> dict[str, LegGroup]:
    """The group of every registered robot, by robot name."""
    return {name: robot_group(name) for name in registered_robots()}

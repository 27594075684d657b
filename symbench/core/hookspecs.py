"""pluggy hook specifications of the `symbench` project.

A plugin is any module or object with functions marked `@symbench.hookimpl` whose names
match these. Each collection hook returns a list of entries (see `symbench.core.entries`);
a plugin implements only the hooks it needs.
"""

from __future__ import annotations

import click
import pluggy

hookspec = pluggy.HookspecMarker("symbench")
hookimpl = pluggy.HookimplMarker("symbench")


@hookspec
def symbench_models() -> list:
    """Model architectures: a list of `ModelEntry`, one per (name, backend)."""


@hookspec
def symbench_robots() -> list:
    """Robots: a list of `RobotEntry`, each pointing at a spec folder with robot.toml."""


@hookspec
def symbench_evaluators() -> list:
    """Evaluators: a list of `EvaluatorEntry` that turn a trained model into metrics."""


@hookspec
def symbench_splits() -> list:
    """Dataset splits: a list of `SplitEntry` that partition trajectories."""


@hookspec
def symbench_commands(cli: click.Group) -> None:
    """Add commands to the `symbench` click group (`cli.add_command(...)`)."""

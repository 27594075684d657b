"""pluggy hook specifications of the `symbench` project.

A plugin is any module or object with functions marked `@symbench.hookimpl` whose names
match these. Each collection hook returns a list of entries (see `symbench.core.plugin.entries`),
checked when they are made; a plugin implements only the hooks it needs.
"""

from __future__ import annotations

from collections.abc import Sequence

import click
import pluggy

from symbench.core.plugin.entries import EvaluatorEntry, ModelEntry, RobotEntry, SplitEntry

hookspec = pluggy.HookspecMarker("symbench")
hookimpl = pluggy.HookimplMarker("symbench")


@hookspec
def symbench_models() -> Sequence[ModelEntry]:  # type: ignore[empty-body]
    """Model architectures: one `ModelEntry` per (name, backend)."""


@hookspec
def symbench_robots() -> Sequence[RobotEntry]:  # type: ignore[empty-body]
    """Robots: `RobotEntry`s, each pointing at a spec folder with robot.toml."""


@hookspec
def symbench_evaluators() -> Sequence[EvaluatorEntry]:  # type: ignore[empty-body]
    """Evaluators: `EvaluatorEntry`s that turn a trained model into metrics."""


@hookspec
def symbench_splits() -> Sequence[SplitEntry]:  # type: ignore[empty-body]
    """Dataset splits: `SplitEntry`s that partition trajectories."""


@hookspec
def symbench_commands(cli: click.Group) -> None:
    """Add commands to the `symbench` click group (`cli.add_command(...)`)."""

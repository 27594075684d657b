"""What the collection hooks return: one small record per registered thing.

Entries are plain frozen dataclasses so that listing them (`symbench list`) never has to
build a network or load a robot. The callables are invoked only when the thing is used.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, fields
from pathlib import Path
from typing import Any

BACKENDS = ("torch", "jax")


@dataclass(frozen=True)
class ModelEntry:
    """A network for one backend, the view it consumes and the symmetry it claims.

    `build(dims, **hyper)` returns the backend's network; `equivariant` says whether the
    model claims equivariance under the robot's symmetry group (checked by the kit).
    """

    name: str
    backend: str
    view: str
    variant: str
    equivariant: bool
    build: Callable[..., Any]
    learning_rate: float = 1e-3
    description: str = ""


@dataclass(frozen=True)
class RobotEntry:
    """A robot whose spec (robot.toml and README.md) lives in `spec_dir`."""

    name: str
    spec_dir: Path
    description: str = ""


@dataclass(frozen=True)
class EvaluatorEntry:
    """An evaluator: `evaluate(context)` returns a dict of metrics."""

    name: str
    evaluate: Callable[..., dict]
    description: str = ""


@dataclass(frozen=True)
class SplitEntry:
    """A split: `assign(context)` labels each trajectory train, val, test or unused.

    `context` is a `symbench.core.splits.SplitContext` (scenarios, trajectory ids, sample
    counts, the robot's rotation order and the seed); see CONTRIBUTING.md.
    """

    name: str
    assign: Callable[..., Any]
    description: str = ""


def describe(entry: Any) -> dict[str, Any]:
    """The entry's plain fields (no callables), JSON-ready."""
    out = {}
    for f in fields(entry):
        value = getattr(entry, f.name)
        if callable(value):
            continue
        out[f.name] = str(value) if isinstance(value, Path) else value
    return out

"""Plugins that get things wrong in the ways a careless plugin does, for the tests that show
symbench naming them instead of tracing back or going on with a wrong result."""

from __future__ import annotations

import contextlib
from collections.abc import Iterator
from pathlib import Path
from typing import Any

from symbench import hookimpl
from symbench.core.data.views.model_dims import ModelDims
from symbench.core.plugin.entries import EvaluatorEntry, ModelEntry, RobotEntry
from symbench.core.plugin.host import PluginHost, set_host

# how a network's torques can be misshaped: (N, legs, 1) broadcasts against (N, legs, 3)
SHAPES = ("squeezed", "flat")


def build_torch(dims: ModelDims, shape: str) -> Any:
    import torch

    legs, features = dims.shape("x")

    class Misshaped(torch.nn.Module):
        def __init__(self) -> None:
            super().__init__()
            self.squeezed = torch.nn.Linear(features, 1)
            self.flat = torch.nn.Linear(legs * features, legs * 3)

        def forward(self, x: torch.Tensor) -> torch.Tensor:
            return self.squeezed(x) if shape == "squeezed" else self.flat(x.flatten(1))

    return Misshaped()


def build_jax(dims: ModelDims, shape: str) -> Any:
    import flax.linen as nn

    legs, _ = dims.shape("x")

    class Misshaped(nn.Module):
        @nn.compact
        def __call__(self, x):
            if shape == "squeezed":
                return nn.Dense(1)(x)
            return nn.Dense(legs * 3)(x.reshape(len(x), -1))

    return Misshaped()


def misshaped(shape: str, backend: str) -> ModelEntry:
    """A model whose torques are shaped `shape` instead of (N, legs, 3)."""
    build = build_torch if backend == "torch" else build_jax
    return ModelEntry(
        f"{shape}-net", backend, "leg_grouped", "acc", False, lambda dims: build(dims, shape)
    )


def _no_plan(context) -> list:
    raise KeyError("split")


class BadPlugin:
    @hookimpl
    def symbench_models(self) -> list:
        return [misshaped(shape, backend) for shape in SHAPES for backend in ("torch", "jax")]

    @hookimpl
    def symbench_evaluators(self) -> list:
        return [
            EvaluatorEntry("pairs", evaluate=lambda context: [("rmse", 1.0)]),
            EvaluatorEntry("plans-badly", evaluate=lambda context: {}, trainings=_no_plan),
            EvaluatorEntry(
                "plans-from-samples",
                evaluate=lambda context: {},
                trainings=lambda context: [(None, "iid", context.test.variant)],
            ),
        ]

    @hookimpl
    def symbench_robots(self) -> Any:
        return RobotEntry("tripod", Path("/nowhere"))  # the entry itself, not a list of it


@contextlib.contextmanager
def bad_plugin_installed() -> Iterator[PluginHost]:
    """The built-in plugins and BadPlugin, for the commands run inside the block."""
    host = PluginHost()
    host.load_entry_points("none")
    host.register(BadPlugin(), "bad")
    set_host(host)
    try:
        yield host
    finally:
        set_host(None)

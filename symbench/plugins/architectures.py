"""Default sizes of the built-in architectures: the one place both backends read them from.

The torch and JAX twins of a model must be the same network for their results to be
comparable, so neither keeps numbers of its own: each backend's `build` is made by `builder`
from the instances below, and the zoo's descriptions quote them. A run records every keyword
the build function receives, read from its signature: `builder` writes the fields, with
these defaults, into that signature.
tests/models/test_backend_parity.py checks that the twins compute the same function.

The values are those the published leaderboard was trained with: changing one changes the
networks' parameter shapes, and the board no longer describes the code.
"""

from __future__ import annotations

import inspect
from collections.abc import Callable
from dataclasses import dataclass, fields, replace
from typing import Any, TypeVar

import numpy as np

from symbench import ModelDims, SymbenchError, schema

LAYER_NORM_EPS = 1e-5
"""Epsilon of every LatentMLP's LayerNorm: torch's default, which flax's (1e-6) is not."""


@dataclass(frozen=True)
class MLPSizes:
    """ffnn (and ffnn-leg): `layers` hidden layers of `width` units."""

    width: int
    layers: int


@dataclass(frozen=True)
class SDNNSizes:
    """sdnn: per-leg MLPs of `mlp_layers` layers and `latent` units; `steps` processing steps;
    `mirror` 1 averages the network with its leg-mirrored image (`mirror_signs`); `ring` 1
    also gives each leg its two neighbours' latents in every step (`check_ring`)."""

    latent: int
    mlp_layers: int
    steps: int
    mirror: int = 0
    ring: int = 0


@dataclass(frozen=True)
class GraphSizes:
    """gnn and sdgnn: latent widths of edges, nodes and the global; MLP depth; message-passing
    steps."""

    edge: int
    node: int
    glob: int
    mlp_layers: int
    steps: int


@dataclass(frozen=True)
class SDGNNSizes(GraphSizes):
    """sdgnn: a graph network's sizes, and `mirror` as sdnn's."""

    mirror: int = 0


FFNN = MLPSizes(width=256, layers=3)
SDNN = SDNNSizes(latent=128, mlp_layers=2, steps=2)
GNN = GraphSizes(edge=64, node=16, glob=16, mlp_layers=2, steps=5)
SDGNN = SDGNNSizes(edge=64, node=16, glob=16, mlp_layers=2, steps=2)


def as_tuples(signs: tuple[np.ndarray, np.ndarray] | None) -> tuple | None:
    """`mirror_signs` as nested tuples of floats: what a flax module may hold as a field."""
    return None if signs is None else tuple(tuple(float(v) for v in s) for s in signs)


Sizes = TypeVar("Sizes", MLPSizes, SDNNSizes, GraphSizes, SDGNNSizes)


def mirror_signs(dims: ModelDims, mirror: int) -> tuple[np.ndarray, np.ndarray] | None:
    """For `mirror` 1, the leg mirror's per-feature signs on a leg-grouped model's inputs and
    torques (the schema's, float32); None for 0.

    A network f that is equivariant to every permutation of legs becomes equivariant to the
    robot's mirrors too as (f(x) + s_out f(s_in x)) / 2: a mirror relabels legs and flips
    these signs in every leg, so the average is the same function of x and of its mirror
    image. The network keeps its parameters; each call costs two passes (one batch of two).
    """
    if mirror not in (0, 1):
        raise SymbenchError(f"mirror must be 0 or 1, got {mirror!r}")
    if not mirror:
        return None
    inputs = schema.leg_grouped_input(dims.variant).reflection_signs
    return np.asarray(inputs, np.float32), np.asarray(schema.TARGET.reflection_signs, np.float32)


def check_ring(ring: int, mirror: int) -> bool:
    """Whether the processing steps see the neighbours (legs i + 1 and i - 1, cyclically).

    A network that shares weights across legs and sums over them is equivariant to every
    permutation of the legs: more than any robot's group, and blind to which legs are
    neighbours. Legs are numbered around the body (each robot's rotations shift them
    cyclically), so giving leg i the latents of legs i + 1 and i - 1, in that order, keeps
    the network equivariant to the robot's rotations and narrows it to them: an ablation of
    that over-constraint. The mirror average assumes every permutation (a mirror swaps the
    two neighbours), so the two are not combined."""
    if ring not in (0, 1):
        raise SymbenchError(f"ring must be 0 or 1, got {ring!r}")
    if ring and mirror:
        raise SymbenchError("ring and mirror cannot be combined")
    return bool(ring)


def builder(defaults: Sizes, make: Callable[[ModelDims, Sizes], Any]) -> Callable[..., Any]:
    """`build(dims, **sizes)` for a `ModelEntry`: `make(dims, defaults with sizes replaced)`,
    its signature naming every size with its default; an unknown size is a TypeError."""
    names = [f.name for f in fields(defaults)]

    def build(dims: ModelDims, **sizes: int) -> Any:
        unknown = sorted(set(sizes) - set(names))
        if unknown:
            raise TypeError(f"unknown size(s) {', '.join(unknown)} (known: {', '.join(names)})")
        return make(dims, replace(defaults, **sizes))

    keyword = inspect.Parameter.POSITIONAL_OR_KEYWORD
    build.__signature__ = inspect.Signature(  # type: ignore[attr-defined]
        [inspect.Parameter("dims", keyword, annotation=ModelDims)]
        + [
            inspect.Parameter(n, keyword, default=getattr(defaults, n), annotation=int)
            for n in names
        ]
    )
    return build

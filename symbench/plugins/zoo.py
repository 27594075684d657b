"""The built-in architectures, registered once per backend with the same names and defaults.

Each backend package holds one module per architecture with a `build(dims, **hyper)`, whose
default sizes both backends read from `architectures` (and so do the descriptions below);
`ffnn-leg` is the `ffnn` network fed the flattened leg-grouped view, which separates the
effect of the representation from that of the architecture.

Versions (records carry them, `verify` refuses another): 2 where issue 39's speed-up changed
the float summation order (torch: sdnn's leg sum through its own weight block, the graph
networks' edge-major layout; JAX: every weight gradient through an explicit transpose, sdnn's
and the graph networks' concatenations multiplied block by block); torch's ffnn and ffnn-leg
train bit for bit as before (a TorchScript trace of the same operations) and stay at 1.
"""

from __future__ import annotations

from dataclasses import dataclass

from symbench import Lazy, ModelEntry
from symbench.plugins.architectures import FFNN, GNN, SDGNN, SDNN


@dataclass(frozen=True)
class Architecture:
    name: str
    module: str  # file in the backend package holding `build`
    view: str
    equivariant: bool
    learning_rate: float  # chosen by `symbench tune` (leaderboards/tuning/README.md)
    description: str
    widths: tuple[str, ...]  # the build keywords `symbench tune` scales together
    # per backend, raised whenever what its network computes changes (ModelEntry.version)
    versions: dict[str, int]


ARCHITECTURES = (
    Architecture(
        "ffnn",
        "ffnn",
        "vector",
        False,
        3e-3,
        f"MLP ({FFNN.layers} x {FFNN.width}) on the stacked world-frame vector",
        ("width",),
        {"torch": 1, "jax": 2},
    ),
    Architecture(
        "ffnn-leg",
        "ffnn",
        "leg_grouped",
        False,
        1e-3,
        "the ffnn MLP on the flattened leg-grouped view",
        ("width",),
        {"torch": 1, "jax": 2},
    ),
    Architecture(
        "gnn",
        "gnn",
        "body_graph",
        False,
        3e-3,
        f"typical graph network (bodies as nodes, joints as edges), {GNN.steps} steps",
        ("edge", "node", "glob"),
        {"torch": 2, "jax": 2},
    ),
    Architecture(
        "sdgnn",
        "sdgnn",
        "leg_grouped",
        True,
        1e-3,
        f"symmetric graph network: base and feet as nodes, legs as edges, {SDGNN.steps} steps",
        ("edge", "node", "glob"),
        {"torch": 2, "jax": 2},
    ),
    Architecture(
        "sdnn",
        "sdnn",
        "leg_grouped",
        True,
        1.5e-3,
        f"shared per-leg MLPs, sum over legs, {SDNN.steps} processing steps",
        ("latent",),
        {"torch": 2, "jax": 2},
    ),
)


def model_entries(backend: str, package: str, variant: str = "acc") -> list[ModelEntry]:
    return [
        ModelEntry(
            a.name,
            backend,
            a.view,
            variant,
            a.equivariant,
            Lazy(f"{package}.{a.module}:build"),
            a.learning_rate,
            a.description,
            a.widths,
            a.versions[backend],
        )
        for a in ARCHITECTURES
    ]

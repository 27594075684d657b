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
JAX 3: every model feature-major inside (LayerNorm sums over another axis, the graph
networks gather and sum by index instead of by matrix products, Adam updates the small
arrays as one vector), and a call of at most 32 rows (legs or edges times samples: a
control loop's batch-1 call) multiplies row-major, which rounds its predictions differently;
torch's training is bit for bit that of version 2 (1 for ffnn).
JAX 4: predictions and validation losses run the network on 256 rows at a time (a longer call
as pieces of exactly 256 rows, the last one padded), where version 3 ran a whole call (a
validation check: up to 8 192 rows) at once; training steps are those of version 3.
"""

from __future__ import annotations

import tomllib
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from symbench import BACKENDS, InvalidEntryError, Lazy, ModelEntry
from symbench.plugins.architectures import FFNN, GNN, SDGNN, SDNN

# model -> backend -> robot -> learning rate, chosen per robot by `symbench tune --robot R`
TUNED_RATES = Path(__file__).with_name("tuned_rates.toml")


@dataclass(frozen=True)
class Architecture:
    name: str
    module: str  # file in the backend package holding `build`
    view: str
    equivariant: bool
    # chosen by `symbench tune` on hexa, for every robot not in tuned_rates.toml
    # (leaderboards/tuning/README.md)
    learning_rate: float
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
        {"torch": 1, "jax": 4},
    ),
    Architecture(
        "ffnn-leg",
        "ffnn",
        "leg_grouped",
        False,
        1e-3,
        "the ffnn MLP on the flattened leg-grouped view",
        ("width",),
        {"torch": 1, "jax": 4},
    ),
    Architecture(
        "gnn",
        "gnn",
        "body_graph",
        False,
        3e-3,
        f"typical graph network (bodies as nodes, joints as edges), {GNN.steps} steps",
        ("edge", "node", "glob"),
        {"torch": 2, "jax": 4},
    ),
    Architecture(
        "sdgnn",
        "sdgnn",
        "leg_grouped",
        True,
        1e-3,
        f"symmetric graph network: base and feet as nodes, legs as edges, {SDGNN.steps} steps",
        ("edge", "node", "glob"),
        {"torch": 2, "jax": 4},
    ),
    Architecture(
        "sdnn",
        "sdnn",
        "leg_grouped",
        True,
        1.5e-3,
        f"shared per-leg MLPs, sum over legs, {SDNN.steps} processing steps",
        ("latent",),
        {"torch": 2, "jax": 4},
    ),
)


def tuned_rates(path: Path) -> dict[str, dict[str, Any]]:
    """The per-robot rates of `path` by model and backend; a model or backend it names that
    does not exist is refused (a misspelt name would otherwise leave its rates unused)."""
    try:
        tables = tomllib.loads(path.read_text())
    except tomllib.TOMLDecodeError as error:
        raise InvalidEntryError(f"{path.name}: not valid TOML ({error})") from None
    for model, backends in tables.items():
        if model not in {a.name for a in ARCHITECTURES}:
            raise InvalidEntryError(f"{path.name}: no built-in model '{model}'")
        if not isinstance(backends, dict):
            raise InvalidEntryError(f"{path.name}: '{model}' is not a table of backends")
        unknown = sorted(set(backends) - set(BACKENDS))
        if unknown:
            raise InvalidEntryError(f"{path.name}: model '{model}' has no backend '{unknown[0]}'")
    return tables


def model_entries(backend: str, package: str, variant: str = "acc") -> list[ModelEntry]:
    rates = tuned_rates(TUNED_RATES)
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
            rates.get(a.name, {}).get(backend, {}),
        )
        for a in ARCHITECTURES
    ]

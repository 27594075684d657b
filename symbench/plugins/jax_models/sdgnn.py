"""SD-GNN: base and feet as nodes, legs as edges carrying the leg-grouped features.

Every leg is the same kind of edge and aggregation is a sum, so permuting legs permutes the
edge outputs: the network is equivariant to the robot's rotation group.
"""

from __future__ import annotations

from dataclasses import asdict

import flax.linen as nn
import jax.numpy as jnp

from symbench.plugins.architectures import SDGNN as DEFAULTS
from symbench.plugins.architectures import as_tuples, builder, mirror_signs
from symbench.plugins.graphs import star_graph
from symbench.plugins.jax_models.layers import GraphNetwork, mirror_average


class SDGNN(nn.Module):
    n_legs: int
    sizes: dict
    signs: tuple | None = None  # the leg mirror's (input, output) signs, as tuples

    @nn.compact
    def __call__(self, x: jnp.ndarray) -> jnp.ndarray:
        return mirror_average(x, self.equivariant, self.signs)

    def equivariant(self, x: jnp.ndarray) -> jnp.ndarray:
        """The network itself: equivariant to every permutation of legs."""
        edges, types = star_graph(self.n_legs)
        n = x.shape[0]
        nodes = jnp.broadcast_to(jnp.asarray(types, x.dtype), (n, *types.shape))
        return GraphNetwork(edges, 3, **self.sizes, name="graph")(
            nodes, x, jnp.ones((n, 1), x.dtype)
        )


def _make(dims, sizes) -> SDGNN:
    graph = {k: v for k, v in asdict(sizes).items() if k != "mirror"}
    return SDGNN(dims.n_legs, graph, as_tuples(mirror_signs(dims, sizes.mirror)))


build = builder(DEFAULTS, _make)

"""SD-GNN: base and feet as nodes, legs as edges carrying the leg-grouped features.

Every leg is the same kind of edge and aggregation is a sum, so permuting legs permutes the
edge outputs: the network is equivariant to the robot's rotation group.
"""

from __future__ import annotations

from dataclasses import asdict

import flax.linen as nn
import jax.numpy as jnp

from symbench.plugins.architectures import SDGNN as DEFAULTS
from symbench.plugins.architectures import builder
from symbench.plugins.graphs import star_graph
from symbench.plugins.jax_models.layers import GraphNetwork


class SDGNN(nn.Module):
    n_legs: int
    sizes: dict

    @nn.compact
    def __call__(self, x: jnp.ndarray) -> jnp.ndarray:
        edges, types = star_graph(self.n_legs)
        n = x.shape[0]
        nodes = jnp.broadcast_to(jnp.asarray(types, x.dtype), (n, *types.shape))
        return GraphNetwork(edges, 3, **self.sizes, name="graph")(
            nodes, x, jnp.ones((n, 1), x.dtype)
        )


build = builder(DEFAULTS, lambda dims, s: SDGNN(dims.n_legs, asdict(s)))

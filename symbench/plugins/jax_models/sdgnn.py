"""SD-GNN: base and feet as nodes, legs as edges carrying the leg-grouped features.

Every leg is the same kind of edge and aggregation is a sum, so permuting legs permutes the
edge outputs: the network is equivariant to the robot's rotation group.
"""

from __future__ import annotations

import flax.linen as nn
import jax.numpy as jnp

from symbench import ModelDims
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


def build(
    dims: ModelDims,
    edge: int = 64,
    node: int = 16,
    glob: int = 16,
    mlp_layers: int = 2,
    steps: int = 2,
) -> SDGNN:
    return SDGNN(
        dims.n_legs, dict(edge=edge, node=node, glob=glob, mlp_layers=mlp_layers, steps=steps)
    )

"""The typical GNN: bodies as nodes, joints as edges, base state as global; one torque per edge."""

from __future__ import annotations

import flax.linen as nn
import jax.numpy as jnp
import numpy as np

from symbench import ModelDims, schema
from symbench.plugins.architectures import GNN as DEFAULTS
from symbench.plugins.jax_models.layers import GraphNetwork


class GNN(nn.Module):
    n_legs: int
    edge_index: np.ndarray
    sizes: dict

    @nn.compact
    def __call__(self, nodes: jnp.ndarray, edges: jnp.ndarray, globals: jnp.ndarray) -> jnp.ndarray:
        y = GraphNetwork(self.edge_index, 1, **self.sizes, name="graph")(nodes, edges, globals)
        return y.reshape(-1, self.n_legs, 3)


def build(
    dims: ModelDims,
    edge: int = DEFAULTS.edge,
    node: int = DEFAULTS.node,
    glob: int = DEFAULTS.glob,
    mlp_layers: int = DEFAULTS.mlp_layers,
    steps: int = DEFAULTS.steps,
) -> GNN:
    sizes = dict(edge=edge, node=node, glob=glob, mlp_layers=mlp_layers, steps=steps)
    return GNN(dims.n_legs, schema.body_graph(dims.n_legs, dims.variant).edges(), sizes)

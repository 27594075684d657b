"""The typical GNN: bodies as nodes, joints as edges, base state as global; one torque per edge."""

from __future__ import annotations

from dataclasses import asdict

import flax.linen as nn
import jax.numpy as jnp
import numpy as np

from symbench import schema
from symbench.plugins.architectures import GNN as DEFAULTS
from symbench.plugins.architectures import builder
from symbench.plugins.jax_models.layers import GraphNetwork


class GNN(nn.Module):
    n_legs: int
    edge_index: np.ndarray
    sizes: dict

    @nn.compact
    def __call__(self, nodes: jnp.ndarray, edges: jnp.ndarray, globals: jnp.ndarray) -> jnp.ndarray:
        y = GraphNetwork(self.edge_index, 1, **self.sizes, name="graph")(nodes, edges, globals)
        return y.reshape(-1, self.n_legs, 3)


build = builder(
    DEFAULTS,
    lambda dims, s: GNN(
        dims.n_legs, schema.body_graph(dims.n_legs, dims.variant).edges(), asdict(s)
    ),
)

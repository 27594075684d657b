"""FFNN: an MLP on a flat input (the `vector` view, or the flattened `leg_grouped` view)."""

from __future__ import annotations

import flax.linen as nn
import jax.numpy as jnp

from symbench.plugins.architectures import FFNN as DEFAULTS
from symbench.plugins.architectures import builder
from symbench.plugins.jax_models.layers import Dense, LatentMLP


class FFNN(nn.Module):
    n_legs: int
    width: int
    layers: int

    @nn.compact
    def __call__(self, x: jnp.ndarray) -> jnp.ndarray:
        h = LatentMLP(self.width, self.layers, name="body")(x.reshape(x.shape[0], -1))
        return Dense(3 * self.n_legs, name="out")(h).reshape(-1, self.n_legs, 3)


build = builder(DEFAULTS, lambda dims, s: FFNN(dims.n_legs, s.width, s.layers))

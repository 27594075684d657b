"""FFNN: an MLP on a flat input (the `vector` view, or the flattened `leg_grouped` view)."""

from __future__ import annotations

import flax.linen as nn
import jax.numpy as jnp

from symbench.plugins.architectures import FFNN as DEFAULTS
from symbench.plugins.architectures import builder
from symbench.plugins.jax_models.layers import Dense, LatentMLP, features_first


class FFNN(nn.Module):
    n_legs: int
    width: int
    layers: int

    @nn.compact
    def __call__(self, x: jnp.ndarray) -> jnp.ndarray:
        # feature-major inside (layers.Dense): (feature, batch)
        h = LatentMLP(self.width, self.layers, name="body")(features_first(x.reshape(len(x), -1)))
        return features_first(Dense(3 * self.n_legs, name="out")(h)).reshape(-1, self.n_legs, 3)


build = builder(DEFAULTS, lambda dims, s: FFNN(dims.n_legs, s.width, s.layers))

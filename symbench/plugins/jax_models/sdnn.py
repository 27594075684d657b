"""SDNN: one MLP shared by all legs, with repeated steps that see the sum over legs.

Sharing weights across legs and aggregating by a sum make the network equivariant to every
permutation of legs, hence to the robot's rotation group.
"""

from __future__ import annotations

import flax.linen as nn
import jax.numpy as jnp

from symbench.plugins.architectures import SDNN as DEFAULTS
from symbench.plugins.architectures import builder
from symbench.plugins.jax_models.layers import LatentMLP


class SDNN(nn.Module):
    latent: int
    mlp_layers: int
    steps: int

    @nn.compact
    def __call__(self, x: jnp.ndarray) -> jnp.ndarray:
        h = LatentMLP(self.latent, self.mlp_layers, name="enc")(x)
        for k in range(self.steps):
            total = jnp.broadcast_to(h.sum(axis=1, keepdims=True), h.shape)
            h = h + LatentMLP(self.latent, self.mlp_layers, name=f"proc{k}")(
                jnp.concatenate([h, total], axis=-1)
            )
        h = LatentMLP(self.latent, self.mlp_layers, name="dec")(h)
        return nn.Dense(3, name="out")(h)


build = builder(DEFAULTS, lambda dims, s: SDNN(s.latent, s.mlp_layers, s.steps))

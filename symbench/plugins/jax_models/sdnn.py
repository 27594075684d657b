"""SDNN: one MLP shared by all legs, with repeated steps that see the sum over legs.

Sharing weights across legs and aggregating by a sum make the network equivariant to every
permutation of legs, hence to the robot's rotation group.
"""

from __future__ import annotations

import flax.linen as nn
import jax.numpy as jnp

from symbench.plugins.architectures import SDNN as DEFAULTS
from symbench.plugins.architectures import as_tuples, builder, mirror_signs
from symbench.plugins.jax_models.layers import LatentMLP, mirror_average


class SDNN(nn.Module):
    latent: int
    mlp_layers: int
    steps: int
    signs: tuple | None = None  # the leg mirror's (input, output) signs, as tuples

    @nn.compact
    def __call__(self, x: jnp.ndarray) -> jnp.ndarray:
        return mirror_average(x, self.equivariant, self.signs)

    def equivariant(self, x: jnp.ndarray) -> jnp.ndarray:
        """The network itself: equivariant to every permutation of legs."""
        h = LatentMLP(self.latent, self.mlp_layers, name="enc")(x)
        for k in range(self.steps):
            total = jnp.broadcast_to(h.sum(axis=1, keepdims=True), h.shape)
            h = h + LatentMLP(self.latent, self.mlp_layers, name=f"proc{k}")(
                jnp.concatenate([h, total], axis=-1)
            )
        h = LatentMLP(self.latent, self.mlp_layers, name="dec")(h)
        return nn.Dense(3, name="out")(h)


build = builder(
    DEFAULTS,
    lambda dims, s: SDNN(s.latent, s.mlp_layers, s.steps, as_tuples(mirror_signs(dims, s.mirror))),
)

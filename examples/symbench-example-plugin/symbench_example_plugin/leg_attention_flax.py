"""Leg attention in Flax: the JAX twin of `leg_attention`, registered for the jax backend.

The same architecture as the torch module (per-leg MLP, self-attention across legs without
positional encodings, per-leg decoder), written with `flax.linen`: `build` returns a module
whose `__call__(x)` maps the leg-grouped view (N, legs, F) to torques (N, legs, 3).
Parameters are Flax's own: the two backends' checkpoints of this model do not convert.
"""

from __future__ import annotations

import flax.linen as nn
import jax.numpy as jnp

from symbench import ModelDims


class LegAttention(nn.Module):
    latent: int
    heads: int

    @nn.compact
    def __call__(self, x: jnp.ndarray) -> jnp.ndarray:  # (N, legs, F) -> (N, legs, 3)
        h = nn.LayerNorm()(nn.relu(nn.Dense(self.latent)(x)))
        attended = nn.MultiHeadDotProductAttention(num_heads=self.heads)(h, h)
        h = nn.LayerNorm()(h + attended)
        return nn.Dense(3)(nn.relu(nn.Dense(self.latent)(h)))


def build(dims: ModelDims, latent: int = 64, heads: int = 4) -> LegAttention:
    del dims  # Dense layers take their input width from the data
    return LegAttention(latent, heads)

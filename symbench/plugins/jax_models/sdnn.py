"""SDNN: one MLP shared by all legs, with repeated steps that see the sum over legs.

Sharing weights across legs and aggregating by a sum make the network equivariant to every
permutation of legs, hence to the robot's rotation group; with `ring` 1 each step also sees
the two neighbouring legs, which narrows it to the rotations (`architectures.check_ring`).
"""

from __future__ import annotations

import flax.linen as nn
import jax.numpy as jnp

from symbench.plugins.architectures import SDNN as DEFAULTS
from symbench.plugins.architectures import as_tuples, builder, check_ring, mirror_signs
from symbench.plugins.jax_models.layers import (
    Dense,
    LatentMLP,
    features_first,
    mirror_average,
)


class SDNN(nn.Module):
    latent: int
    mlp_layers: int
    steps: int
    signs: tuple | None = None  # the leg mirror's (input, output) signs, as tuples
    ring: bool = False  # each step also sees legs i + 1 and i - 1

    @nn.compact
    def __call__(self, x: jnp.ndarray) -> jnp.ndarray:
        return mirror_average(x, self.equivariant, self.signs)

    def equivariant(self, x: jnp.ndarray) -> jnp.ndarray:
        """The network itself: equivariant to every permutation of legs (with `ring`, to
        the cyclic shifts only)."""
        # feature-major inside (layers.Dense): (feature, leg, batch)
        h = LatentMLP(self.latent, self.mlp_layers, name="enc")(features_first(x))
        for k in range(self.steps):
            seen = [h, h.sum(axis=1, keepdims=True)]  # the sum: once per robot, not per leg
            if self.ring:
                seen += [jnp.roll(h, -1, axis=1), jnp.roll(h, 1, axis=1)]
            h = h + LatentMLP(self.latent, self.mlp_layers, name=f"proc{k}")(*seen)
        h = LatentMLP(self.latent, self.mlp_layers, name="dec")(h)
        return features_first(Dense(3, name="out")(h))


build = builder(
    DEFAULTS,
    lambda dims, s: SDNN(
        s.latent,
        s.mlp_layers,
        s.steps,
        as_tuples(mirror_signs(dims, s.mirror)),
        check_ring(s.ring, s.mirror),
    ),
)

"""A model that claims equivariance and breaks it: SDNN plus a bias that depends on the leg.

The bias starts at zero, as learned embeddings often do; the kit perturbs every parameter,
so it must still catch it.
"""

from __future__ import annotations

from symbench.core.common.lazy import Lazy
from symbench.core.plugin.entries import ModelEntry
from symbench.core.plugin.hookspecs import hookimpl


def build_torch(dims, latent: int = 16):
    import torch

    from symbench.plugins.torch_models.sdnn import SDNN

    class LegBiasedSDNN(SDNN):
        def __init__(self):
            super().__init__(dims.shape("x")[-1], latent, 2, 1)
            self.leg_bias = torch.nn.Parameter(torch.zeros(dims.n_legs, 3))

        def forward(self, x):
            return super().forward(x) + self.leg_bias

    return LegBiasedSDNN()


def build_jax(dims, latent: int = 16):
    import flax.linen as nn
    import jax.numpy as jnp

    from symbench.plugins.jax_models.sdnn import SDNN

    class LegBiasedSDNN(nn.Module):
        @nn.compact
        def __call__(self, x):
            bias = self.param("leg_bias", nn.initializers.zeros, (dims.n_legs, 3), jnp.float32)
            return SDNN(latent, 2, 1)(x) + bias

    return LegBiasedSDNN()


ENTRIES = [
    ModelEntry("broken-sdnn", b, "leg_grouped", "acc", True, Lazy(f"{__name__}:build_{b}"))
    for b in ("torch", "jax")
]


@hookimpl
def symbench_models() -> list:
    return ENTRIES

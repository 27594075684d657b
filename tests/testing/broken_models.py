"""Models that claim equivariance and break it.

`broken-sdnn`: SDNN plus a bias that depends on the leg. The bias starts at zero, as learned
embeddings often do; the kit perturbs every parameter, so it must still catch it.

`misframed-legnet`: a leg-grouped network (one MLP shared by every leg, each leg's joints
and flags in, that leg's torques out) that reads the base state in the world frame (the
vector view's base pose, velocities and acceleration: gravity as the world sees it) where
it should read it in the leg frame. Relabelling its legs permutes its outputs exactly, so a
check that permutes legs (the old kit) passes it; turning the robot by a symmetry step
changes its world-frame input, so the physical check fails it.
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


def build_misframed(dims, width: int = 32):
    import torch
    from torch import nn

    n_legs = dims.n_legs
    n_base = 16  # base_pos, base_quat, base_linvel, base_angvel, base_linacc (world frame)

    class MisframedLegNet(nn.Module):
        def __init__(self):
            super().__init__()
            self.mlp = nn.Sequential(
                nn.Linear(9 + 2 + n_base, width), nn.Tanh(), nn.Linear(width, 3)
            )

        def forward(self, x):
            n = x.shape[0]
            base, rest = x[:, :n_base], x[:, n_base:]
            joints = rest[:, : 9 * n_legs].reshape(n, 3, n_legs, 3).transpose(1, 2)
            flags = rest[:, 9 * n_legs :].reshape(n, 2, n_legs).transpose(1, 2)
            world = base[:, None, :].expand(n, n_legs, n_base)  # the wrong frame
            legs = torch.cat([joints.reshape(n, n_legs, 9), flags, world], -1)
            return self.mlp(legs)

    return MisframedLegNet()


ENTRIES = [
    ModelEntry("broken-sdnn", b, "leg_grouped", "acc", True, Lazy(f"{__name__}:build_{b}"))
    for b in ("torch", "jax")
]
MISFRAMED = ModelEntry(
    "misframed-legnet", "torch", "vector", "acc", True, Lazy(f"{__name__}:build_misframed")
)


@hookimpl
def symbench_models() -> list:
    return [*ENTRIES, MISFRAMED]

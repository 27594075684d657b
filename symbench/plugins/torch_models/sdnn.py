"""SDNN: one MLP shared by all legs, with repeated steps that see the sum over legs.

Sharing weights across legs and aggregating by a sum make the network equivariant to every
permutation of legs, hence to the robot's rotation group; with `mirror` 1 it is averaged with
its leg-mirrored image, which makes it equivariant to the robot's mirrors too
(`architectures.mirror_signs`).
"""

from __future__ import annotations

import torch
from torch import nn

from symbench.plugins.architectures import SDNN as DEFAULTS
from symbench.plugins.architectures import builder, mirror_signs
from symbench.plugins.torch_models.layers import LatentMLP, MirrorAverage


class SDNN(nn.Module):
    def __init__(self, n_features: int, latent: int, mlp_layers: int, steps: int, signs=None):
        super().__init__()
        self.steps = steps
        self.mirror = MirrorAverage(signs)
        self.enc = LatentMLP(n_features, latent, mlp_layers)
        for k in range(steps):
            self.add_module(f"proc{k}", LatentMLP(2 * latent, latent, mlp_layers))
        self.dec = LatentMLP(latent, latent, mlp_layers)
        self.out = nn.Linear(latent, 3)

    def forward(self, x: torch.Tensor) -> torch.Tensor:
        return self.mirror(x, self.equivariant)

    def equivariant(self, x: torch.Tensor) -> torch.Tensor:
        """The network itself: equivariant to every permutation of legs."""
        h = self.enc(x)
        for k in range(self.steps):
            total = h.sum(dim=1, keepdim=True).expand_as(h)
            h = h + getattr(self, f"proc{k}")(torch.cat([h, total], dim=-1))
        return self.out(self.dec(h))


build = builder(
    DEFAULTS,
    lambda dims, s: SDNN(
        dims.shape("x")[-1], s.latent, s.mlp_layers, s.steps, mirror_signs(dims, s.mirror)
    ),
)

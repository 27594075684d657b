"""SDNN: one MLP shared by all legs, with repeated steps that see the sum over legs.

Sharing weights across legs and aggregating by a sum make the network equivariant to every
permutation of legs, hence to the robot's rotation group; with `mirror` 1 it is averaged with
its leg-mirrored image, which makes it equivariant to the robot's mirrors too
(`architectures.mirror_signs`); with `ring` 1 each step also sees the two neighbouring legs,
which narrows it to the robot's rotations (`architectures.check_ring`).
"""

from __future__ import annotations

import torch
from torch import nn

from symbench.plugins.architectures import SDNN as DEFAULTS
from symbench.plugins.architectures import builder, check_ring, mirror_signs
from symbench.plugins.torch_models.layers import LatentMLP, MirrorAverage


class SDNN(nn.Module):
    def __init__(
        self,
        n_features: int,
        latent: int,
        mlp_layers: int,
        steps: int,
        signs=None,
        ring: bool = False,
    ):
        super().__init__()
        self.steps, self.ring = steps, ring
        self.mirror = MirrorAverage(signs)
        self.enc = LatentMLP(n_features, latent, mlp_layers)
        seen = (4 if ring else 2) * latent  # itself, the sum (and its two neighbours)
        for k in range(steps):
            self.add_module(f"proc{k}", LatentMLP(seen, latent, mlp_layers))
        self.dec = LatentMLP(latent, latent, mlp_layers)
        self.out = nn.Linear(latent, 3)

    def forward(self, x: torch.Tensor) -> torch.Tensor:
        return self.mirror(x, self.equivariant)

    def equivariant(self, x: torch.Tensor) -> torch.Tensor:
        """The network itself: equivariant to every permutation of legs (with `ring`, to
        the cyclic shifts only)."""
        h = self.enc(x)
        for k in range(self.steps):
            seen = [h, h.sum(dim=1, keepdim=True)]
            if self.ring:
                seen += [torch.roll(h, -1, dims=1), torch.roll(h, 1, dims=1)]
            h = h + getattr(self, f"proc{k}").forward_split(seen)
        return self.out(self.dec(h))


build = builder(
    DEFAULTS,
    lambda dims, s: SDNN(
        dims.shape("x")[-1],
        s.latent,
        s.mlp_layers,
        s.steps,
        mirror_signs(dims, s.mirror),
        check_ring(s.ring, s.mirror),
    ),
)

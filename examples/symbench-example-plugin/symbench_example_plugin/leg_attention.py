"""Leg attention: legs exchange information by self-attention instead of a sum.

Attention without positional encodings is permutation-equivariant, and the same MLPs act on
every leg, so the network is equivariant to any relabelling of legs.
"""

from __future__ import annotations

import torch
from torch import nn

from symbench import ModelDims


class LegAttention(nn.Module):
    def __init__(self, n_features: int, latent: int, heads: int):
        super().__init__()
        self.enc = nn.Sequential(nn.Linear(n_features, latent), nn.ReLU(), nn.LayerNorm(latent))
        self.attn = nn.MultiheadAttention(latent, heads, batch_first=True)
        self.norm = nn.LayerNorm(latent)
        self.dec = nn.Sequential(nn.Linear(latent, latent), nn.ReLU(), nn.Linear(latent, 3))

    def forward(self, x: torch.Tensor) -> torch.Tensor:  # (N, legs, F) -> (N, legs, 3)
        h = self.enc(x)
        h = self.norm(h + self.attn(h, h, h, need_weights=False)[0])
        return self.dec(h)


def build(dims: ModelDims, latent: int = 64, heads: int = 4) -> LegAttention:
    return LegAttention(dims.shape("x")[-1], latent, heads)

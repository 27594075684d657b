"""FFNN: an MLP on a flat input (the `vector` view, or the flattened `leg_grouped` view)."""

from __future__ import annotations

import math

import torch
from torch import nn

from symbench.plugins.architectures import FFNN as DEFAULTS
from symbench.plugins.architectures import builder
from symbench.plugins.torch_models.layers import LatentMLP


class FFNN(nn.Module):
    def __init__(self, n_in: int, n_legs: int, width: int, layers: int):
        super().__init__()
        self.n_legs = n_legs
        self.body = LatentMLP(n_in, width, layers)
        self.out = nn.Linear(width, 3 * n_legs)

    def forward(self, x: torch.Tensor) -> torch.Tensor:
        return self.out(self.body(x.flatten(1))).reshape(-1, self.n_legs, 3)


build = builder(
    DEFAULTS, lambda dims, s: FFNN(math.prod(dims.shape("x")), dims.n_legs, s.width, s.layers)
)

"""SD-GNN: base and feet as nodes, legs as edges carrying the leg-grouped features.

Every leg is the same kind of edge and aggregation is a sum, so permuting legs permutes the
edge outputs: the network is equivariant to the robot's rotation group.
"""

from __future__ import annotations

from dataclasses import asdict

import torch
from torch import nn

from symbench.plugins.architectures import SDGNN as DEFAULTS
from symbench.plugins.architectures import builder
from symbench.plugins.graphs import star_graph
from symbench.plugins.torch_models.layers import GraphNetwork


class SDGNN(nn.Module):
    node_types: torch.Tensor  # a buffer: typed, or mypy reads it through Module.__getattr__

    def __init__(self, n_legs: int, n_features: int, **sizes: int):
        super().__init__()
        edges, types = star_graph(n_legs)
        self.register_buffer("node_types", torch.from_numpy(types), persistent=False)
        self.graph = GraphNetwork((2, n_features, 1), edges, 3, **sizes)

    def forward(self, x: torch.Tensor) -> torch.Tensor:
        n = x.shape[0]
        nodes = self.node_types.to(x.dtype).expand(n, -1, -1)
        return self.graph(nodes, x, x.new_ones(n, 1))


build = builder(DEFAULTS, lambda dims, s: SDGNN(dims.n_legs, dims.shape("x")[-1], **asdict(s)))

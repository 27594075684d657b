"""SD-GNN: base and feet as nodes, legs as edges carrying the leg-grouped features.

Every leg is the same kind of edge and aggregation is a sum, so permuting legs permutes the
edge outputs: the network is equivariant to the robot's rotation group; `mirror` 1 makes it
equivariant to the robot's mirrors too, as for sdnn (`architectures.mirror_signs`).
"""

from __future__ import annotations

from dataclasses import asdict

import torch
from torch import nn

from symbench.plugins.architectures import SDGNN as DEFAULTS
from symbench.plugins.architectures import builder, mirror_signs
from symbench.plugins.graphs import star_graph
from symbench.plugins.torch_models.layers import GraphNetwork, MirrorAverage


class SDGNN(nn.Module):
    node_types: torch.Tensor  # a buffer: typed, or mypy reads it through Module.__getattr__

    def __init__(self, n_legs: int, n_features: int, signs=None, **sizes: int):
        super().__init__()
        self.mirror = MirrorAverage(signs)
        edges, types = star_graph(n_legs)
        self.register_buffer("node_types", torch.from_numpy(types), persistent=False)
        self.graph = GraphNetwork((2, n_features, 1), edges, 3, **sizes)

    def forward(self, x: torch.Tensor) -> torch.Tensor:
        return self.mirror(x, self.equivariant)

    def equivariant(self, x: torch.Tensor) -> torch.Tensor:
        """The network itself: equivariant to every permutation of legs."""
        n = x.shape[0]
        nodes = self.node_types.to(x.dtype).expand(n, -1, -1)
        return self.graph(nodes, x, x.new_ones(n, 1))


def _make(dims, sizes) -> nn.Module:
    graph = {k: v for k, v in asdict(sizes).items() if k != "mirror"}
    return SDGNN(dims.n_legs, dims.shape("x")[-1], mirror_signs(dims, sizes.mirror), **graph)


build = builder(DEFAULTS, _make)

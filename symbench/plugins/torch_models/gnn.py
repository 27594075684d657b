"""The typical GNN: bodies as nodes, joints as edges, base state as global; one torque per edge."""

from __future__ import annotations

from dataclasses import asdict

import torch
from torch import nn

from symbench import ModelDims, schema
from symbench.plugins.architectures import GNN as DEFAULTS
from symbench.plugins.architectures import builder
from symbench.plugins.torch_models.layers import GraphNetwork


class GNN(nn.Module):
    def __init__(self, dims: ModelDims, **sizes: int):
        super().__init__()
        self.n_legs = dims.n_legs
        graph = schema.body_graph(dims.n_legs, dims.variant)
        fin = (dims.shape("nodes")[-1], dims.shape("edges")[-1], dims.shape("globals")[-1])
        self.graph = GraphNetwork(fin, graph.edges(), 1, **sizes)

    def forward(
        self, nodes: torch.Tensor, edges: torch.Tensor, globals: torch.Tensor
    ) -> torch.Tensor:
        return self.graph(nodes, edges, globals).reshape(-1, self.n_legs, 3)


build = builder(DEFAULTS, lambda dims, s: GNN(dims, **asdict(s)))

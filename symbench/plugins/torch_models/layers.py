"""Layers shared by the PyTorch models; names match the flax twins in jax_models/layers.py."""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
import torch
import torch.nn.functional as F
from torch import nn

from symbench.plugins.architectures import LAYER_NORM_EPS
from symbench.plugins.graphs import incidence


class LatentMLP(nn.Module):
    """[Linear, ReLU] x n_layers, then LayerNorm: the paper's 'MLP followed by layer norm'."""

    linear0: nn.Linear  # added by name: typed, or mypy reads it through Module.__getattr__

    def __init__(self, n_in: int, width: int, n_layers: int):
        super().__init__()
        self.n_layers = n_layers
        for i in range(n_layers):
            self.add_module(f"linear{i}", nn.Linear(n_in if i == 0 else width, width))
        self.norm = nn.LayerNorm(width, eps=LAYER_NORM_EPS)

    def forward(self, x: torch.Tensor) -> torch.Tensor:
        return self._rest(self.linear0(x))

    def forward_split(self, parts: Sequence[torch.Tensor]) -> torch.Tensor:
        """`forward(cat(parts, -1))` without the concatenation: each part meets its own column
        block of linear0's weight and the products are summed, broadcasting, so a part shared
        by many rows (sdnn's sum over legs) is multiplied once, not per row. The graph network
        keeps its concatenations: splitting them measured no faster in torch."""
        blocks = self.linear0.weight.split([p.shape[-1] for p in parts], dim=1)
        pre = F.linear(parts[0], blocks[0], self.linear0.bias)
        for part, block in zip(parts[1:], blocks[1:], strict=True):
            pre = pre + F.linear(part, block)
        return self._rest(pre)

    def _rest(self, pre: torch.Tensor) -> torch.Tensor:
        """The layers after linear0's pre-activation."""
        x = torch.relu(pre)
        for i in range(1, self.n_layers):
            x = torch.relu(getattr(self, f"linear{i}")(x))
        return self.norm(x)


class MirrorAverage(nn.Module):
    """Averages a network with its leg-mirrored image, (f(x) + s_out f(s_in x)) / 2, both
    passes in one batch (`architectures.mirror_signs`); without signs it is f itself. It has
    no parameters and its sign buffers are not saved, so the network's checkpoint is the
    same with or without it."""

    s_in: torch.Tensor  # buffers: typed, or mypy reads them through Module.__getattr__
    s_out: torch.Tensor

    def __init__(self, signs: tuple[np.ndarray, np.ndarray] | None):
        super().__init__()
        self.on = signs is not None
        if signs is not None:
            self.register_buffer("s_in", torch.from_numpy(signs[0]), persistent=False)
            self.register_buffer("s_out", torch.from_numpy(signs[1]), persistent=False)

    def forward(self, x: torch.Tensor, f) -> torch.Tensor:
        if not self.on:
            return f(x)
        n = x.shape[0]
        y = f(torch.cat([x, x * self.s_in.to(x.dtype)]))
        return 0.5 * (y[:n] + y[n:] * self.s_out.to(x.dtype))


class GraphNetwork(nn.Module):
    """Encode-process-decode graph network (Battaglia et al. 2018) with sum aggregation.

    Each processing step updates edges from (edge, both end nodes, global), nodes from (node,
    sum of incident edges, global) and the global from (global, sum of edges, sum of nodes),
    residually. The decoder reads every edge: edges carry the outputs.
    """

    def __init__(
        self,
        dims_in: tuple[int, int, int],
        edge_index: np.ndarray,
        n_out: int,
        edge: int,
        node: int,
        glob: int,
        mlp_layers: int,
        steps: int,
    ):
        super().__init__()
        fn, fe, fg = dims_in
        senders, receivers = edge_index[:, 0], edge_index[:, 1]
        self.register_buffer("senders", torch.from_numpy(senders.copy()), persistent=False)
        self.register_buffer("receivers", torch.from_numpy(receivers.copy()), persistent=False)
        self.register_buffer("incidence", torch.from_numpy(incidence(edge_index)), persistent=False)
        self.steps = steps
        self.enc_edge = LatentMLP(fe, edge, mlp_layers)
        self.enc_node = LatentMLP(fn, node, mlp_layers)
        self.enc_global = LatentMLP(fg, glob, mlp_layers)
        for k in range(steps):
            self.add_module(f"edge{k}", LatentMLP(edge + 2 * node + glob, edge, mlp_layers))
            self.add_module(f"node{k}", LatentMLP(node + edge + glob, node, mlp_layers))
            self.add_module(f"global{k}", LatentMLP(glob + edge + node, glob, mlp_layers))
        self.dec = LatentMLP(edge, edge, mlp_layers)
        self.out = nn.Linear(edge, n_out)

    def forward(self, nodes: torch.Tensor, edges: torch.Tensor, glob: torch.Tensor) -> torch.Tensor:
        # inside, features are laid out (node or edge, batch, feature): gathering nodes onto
        # edges selects whole rows and summing edges onto nodes is one 2-D matmul, neither
        # copying to rearrange the batch (training ~5 % faster than batch first)
        v = self.enc_node(nodes.transpose(0, 1))
        e = self.enc_edge(edges.transpose(0, 1))
        u = self.enc_global(glob)
        sum_incident = self.incidence.to(e.dtype)
        for k in range(self.steps):
            n_e, n_v = e.shape[0], v.shape[0]
            ends = [v.index_select(0, self.senders), v.index_select(0, self.receivers)]
            e = e + getattr(self, f"edge{k}")(torch.cat([e, *ends, u.expand(n_e, -1, -1)], -1))
            agg = (sum_incident @ e.flatten(1)).view(n_v, *e.shape[1:])
            v = v + getattr(self, f"node{k}")(torch.cat([v, agg, u.expand(n_v, -1, -1)], -1))
            u = u + getattr(self, f"global{k}")(torch.cat([u, e.sum(0), v.sum(0)], -1))
        return self.out(self.dec(e)).transpose(0, 1)

"""Graph structure shared by the torch and JAX graph networks (plain numpy)."""

from __future__ import annotations

import numpy as np


def star_graph(n_legs: int) -> tuple[np.ndarray, np.ndarray]:
    """SD-GNN graph: edges base (node 0) -> foot i (node i + 1); node types [is_base, is_foot]."""
    edges = np.array([(0, i + 1) for i in range(n_legs)], dtype=np.int64)
    types = np.zeros((n_legs + 1, 2), np.float32)
    types[0, 0], types[1:, 1] = 1.0, 1.0
    return edges, types


def incidence(edge_index: np.ndarray) -> np.ndarray:
    """(n_nodes, n_edges) with ones at both ends of each edge: sums over incident edges."""
    n_edges = len(edge_index)
    out = np.zeros((int(edge_index.max()) + 1, n_edges), np.float32)
    out[edge_index[:, 0], np.arange(n_edges)] = 1.0
    out[edge_index[:, 1], np.arange(n_edges)] = 1.0
    return out

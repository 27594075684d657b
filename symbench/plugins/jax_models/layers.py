"""Layers shared by the JAX/Flax models; names match the torch twins in torch_models/layers.py."""

from __future__ import annotations

import flax.linen as nn
import jax.numpy as jnp
import numpy as np

from symbench.plugins.architectures import LAYER_NORM_EPS
from symbench.plugins.graphs import incidence


class LatentMLP(nn.Module):
    """[Dense, ReLU] x n_layers, then LayerNorm (torch's epsilon and two-pass variance)."""

    width: int
    n_layers: int

    @nn.compact
    def __call__(self, x: jnp.ndarray) -> jnp.ndarray:
        for i in range(self.n_layers):
            x = nn.relu(nn.Dense(self.width, name=f"linear{i}")(x))
        return nn.LayerNorm(epsilon=LAYER_NORM_EPS, use_fast_variance=False, name="norm")(x)


class GraphNetwork(nn.Module):
    """Encode-process-decode graph network with sum aggregation; see the torch twin."""

    edge_index: np.ndarray
    n_out: int
    edge: int
    node: int
    glob: int
    mlp_layers: int
    steps: int

    @nn.compact
    def __call__(self, nodes: jnp.ndarray, edges: jnp.ndarray, glob: jnp.ndarray) -> jnp.ndarray:
        senders, receivers = self.edge_index[:, 0], self.edge_index[:, 1]
        sum_incident = jnp.asarray(incidence(self.edge_index), edges.dtype)
        mlp = self.mlp_layers
        v = LatentMLP(self.node, mlp, name="enc_node")(nodes)
        e = LatentMLP(self.edge, mlp, name="enc_edge")(edges)
        u = LatentMLP(self.glob, mlp, name="enc_global")(glob)
        for k in range(self.steps):
            n, n_e, n_v = e.shape[0], e.shape[1], v.shape[1]
            e = e + LatentMLP(self.edge, mlp, name=f"edge{k}")(
                jnp.concatenate(
                    [
                        e,
                        v[:, senders],
                        v[:, receivers],
                        jnp.broadcast_to(u[:, None], (n, n_e, u.shape[-1])),
                    ],
                    -1,
                )
            )
            agg = jnp.einsum("ve,ned->nvd", sum_incident, e)
            v = v + LatentMLP(self.node, mlp, name=f"node{k}")(
                jnp.concatenate([v, agg, jnp.broadcast_to(u[:, None], (n, n_v, u.shape[-1]))], -1)
            )
            u = u + LatentMLP(self.glob, mlp, name=f"global{k}")(
                jnp.concatenate([u, e.sum(1), v.sum(1)], -1)
            )
        return nn.Dense(self.n_out, name="out")(LatentMLP(self.edge, mlp, name="dec")(e))


def mirror_average(x: jnp.ndarray, f, signs: tuple | None) -> jnp.ndarray:
    """(f(x) + s_out f(s_in x)) / 2 in one batch (`architectures.mirror_signs`), f alone
    without signs: the twin of the torch models' MirrorAverage."""
    if signs is None:
        return f(x)
    n = x.shape[0]
    s_in, s_out = (jnp.asarray(s, x.dtype) for s in signs)
    y = f(jnp.concatenate([x, x * s_in]))
    return 0.5 * (y[:n] + y[n:] * s_out)

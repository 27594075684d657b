"""Layers shared by the JAX/Flax models; names match the torch twins in torch_models/layers.py."""

from __future__ import annotations

import flax.linen as nn
import jax
import jax.numpy as jnp
import numpy as np
from jax import lax

from symbench.plugins.architectures import LAYER_NORM_EPS
from symbench.plugins.graphs import incidence


@jax.custom_vjp
def _matmul(x: jax.Array, kernel: jax.Array) -> jax.Array:
    """x @ kernel over x's last axis, differentiated by `_matmul_bwd`."""
    return lax.dot_general(x, kernel, (((x.ndim - 1,), (0,)), ((), ())))


def _matmul_fwd(x: jax.Array, kernel: jax.Array) -> tuple[jax.Array, tuple]:
    return _matmul(x, kernel), (x, kernel)


def _matmul_bwd(res: tuple, g: jax.Array) -> tuple[jax.Array, jax.Array]:
    """The kernel's gradient x^T g with x^T materialized (the barrier keeps XLA from folding
    the transpose back into the dot): XLA's CPU backend hands YNNPACK only dots whose left
    operand contracts its last axis, and ran the folded form, which contracts the batch axis
    of both, in Eigen at a third of the speed (sdnn on hexa: 45 % of a training step)."""
    x, kernel = res
    dx = lax.dot_general(g, kernel, (((g.ndim - 1,), (1,)), ((), ())))
    rows_t = lax.optimization_barrier(x.reshape(-1, x.shape[-1]).T)
    return dx, rows_t @ g.reshape(-1, g.shape[-1])


_matmul.defvjp(_matmul_fwd, _matmul_bwd)


class Dense(nn.Module):
    """nn.Dense (the same parameters, initialization and function) applied to the
    concatenation of `parts` along the last axis, computed part by part: each part meets its
    block of kernel rows and the products are summed with broadcasting. A part shared by
    several rows (sdnn's sum over legs, a graph's global) is then multiplied once instead
    of once per broadcast copy, and no concatenation is materialized."""

    features: int

    @nn.compact
    def __call__(self, *parts: jax.Array) -> jax.Array:
        sizes = [p.shape[-1] for p in parts]
        kernel = self.param(
            "kernel", nn.initializers.lecun_normal(), (sum(sizes), self.features), jnp.float32
        )
        bias = self.param("bias", nn.initializers.zeros_init(), (self.features,), jnp.float32)
        *inputs, kernel, bias = nn.dtypes.promote_dtype(*parts, kernel, bias)
        blocks = jnp.split(kernel, np.cumsum(sizes)[:-1])
        y = _matmul(inputs[0], blocks[0])
        for part, block in zip(inputs[1:], blocks[1:], strict=True):
            y = y + _matmul(part, block)
        return y + bias


class LatentMLP(nn.Module):
    """[Dense, ReLU] x n_layers, then LayerNorm (torch's epsilon and two-pass variance)."""

    width: int
    n_layers: int

    @nn.compact
    def __call__(self, *parts: jax.Array) -> jax.Array:
        """`parts`: the input as `Dense` takes it (its pieces, concatenated along the last axis)."""
        x = nn.relu(Dense(self.width, name="linear0")(*parts))
        for i in range(1, self.n_layers):
            x = nn.relu(Dense(self.width, name=f"linear{i}")(x))
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
            e = e + LatentMLP(self.edge, mlp, name=f"edge{k}")(
                e, v[:, senders], v[:, receivers], u[:, None]
            )
            agg = jnp.einsum("ve,ned->nvd", sum_incident, e)
            v = v + LatentMLP(self.node, mlp, name=f"node{k}")(v, agg, u[:, None])
            u = u + LatentMLP(self.glob, mlp, name=f"global{k}")(u, e.sum(1), v.sum(1))
        return Dense(self.n_out, name="out")(LatentMLP(self.edge, mlp, name="dec")(e))


def mirror_average(x: jnp.ndarray, f, signs: tuple | None) -> jnp.ndarray:
    """(f(x) + s_out f(s_in x)) / 2 in one batch (`architectures.mirror_signs`), f alone
    without signs: the twin of the torch models' MirrorAverage."""
    if signs is None:
        return f(x)
    n = x.shape[0]
    s_in, s_out = (jnp.asarray(s, x.dtype) for s in signs)
    y = f(jnp.concatenate([x, x * s_in]))
    return 0.5 * (y[:n] + y[n:] * s_out)

"""Layers shared by the JAX/Flax models; names match the torch twins in torch_models/layers.py."""

from __future__ import annotations

import flax.linen as nn
import jax
import jax.numpy as jnp
import numpy as np
from jax import lax

from symbench.plugins.architectures import LAYER_NORM_EPS

# rows (a leg of a robot, an edge of a graph, ...) up to which `_project` multiplies row-major:
# a control loop's batch-1 call (6 to 18 rows), never a training batch (64 samples or more)
FEW_ROWS = 32


@jax.custom_vjp
def _project(x: jax.Array, kernel: jax.Array) -> jax.Array:
    """kernel^T x: x's features (axis 0) through `kernel` (in, out), its other axes the rows,
    differentiated by `_project_bwd`.

    Feature-major, because XLA's CPU backend hands YNNPACK only dots whose left operand
    contracts its last axis: the forward pass then multiplies a transposed copy of the kernel
    (the barrier keeps XLA from folding the transpose back into the dot), and neither
    gradient needs a transposed copy of anything, where the row-major layout (rows, features)
    needed one of every layer's input for its kernel gradient (sdnn on hexa: 13 % of a
    training step, the graph networks' 15 %), each larger than the kernel.

    A call of `FEW_ROWS` rows or fewer multiplies x^T kernel instead (XLA lays the
    transposes out for free): YNNPACK's kernels tile the rows of the result, so the
    feature-major form ran its 128 x 6 results (sdnn on hexa, batch 1) at half the speed
    of the 6 x 128 ones (about 4 against 2 us a dot)."""
    if int(np.prod(x.shape[1:])) <= FEW_ROWS:
        return jnp.moveaxis(lax.dot_general(x, kernel, (((0,), (0,)), ((), ()))), -1, 0)
    kernel_t = lax.optimization_barrier(kernel.T)
    return lax.dot_general(kernel_t, x, (((1,), (0,)), ((), ())))


def _project_fwd(x: jax.Array, kernel: jax.Array) -> tuple[jax.Array, tuple]:
    return _project(x, kernel), (x, kernel)


def _project_bwd(res: tuple, g: jax.Array) -> tuple[jax.Array, jax.Array]:
    """x's gradient kernel g and the kernel's x g^T over the rows: both dots in a form
    YNNPACK takes (the right operand may contract either axis)."""
    x, kernel = res
    dx = lax.dot_general(kernel, g, (((1,), (0,)), ((), ())))
    # the rows as one axis: a dot contracting several is rewritten with its right operand
    # transposed (a copy of g as large as x)
    rows_x, rows_g = x.reshape(len(x), -1), g.reshape(len(g), -1)
    return dx, lax.dot_general(rows_x, rows_g, (((1,), (1,)), ((), ())))


_project.defvjp(_project_fwd, _project_bwd)


def features_first(x: jax.Array) -> jax.Array:
    """(batch, ..., features) -> (features, ..., batch), and back: the layout of `Dense`. The
    batch is the minor axis, along which XLA vectorizes the elementwise loops (a minor axis
    of a robot's 6 legs or 18 joints made them about 3 times slower). Materialized (the
    barrier): folded into a dot, the transpose would send it to a slower library."""
    return lax.optimization_barrier(jnp.transpose(x))


class Dense(nn.Module):
    """nn.Dense (the same parameters and initialization) on feature-major inputs: the
    features along axis 0, rows along the others (`_project`). Given several `parts`, it
    is Dense on their concatenation along the features, computed by groups of parts: a part
    shared by several rows (sdnn's sum over legs, a graph's global) meets its block of
    kernel rows alone and the products are summed with broadcasting, so it is multiplied
    once instead of once per broadcast copy; neighbouring parts of the same rows are
    concatenated, one dot instead of a dot and an output per part (a graph's 16-wide node
    features made small, slow dots: sdgnn +5 %, gnn +4 % samples per second)."""

    features: int

    @nn.compact
    def __call__(self, *parts: jax.Array) -> jax.Array:
        sizes = [p.shape[0] for p in parts]
        kernel = self.param(
            "kernel", nn.initializers.lecun_normal(), (sum(sizes), self.features), jnp.float32
        )
        bias = self.param("bias", nn.initializers.zeros_init(), (self.features,), jnp.float32)
        *inputs, kernel, bias = nn.dtypes.promote_dtype(*parts, kernel, bias)
        groups: list[list[jax.Array]] = []
        for part in inputs:
            if groups and groups[-1][-1].shape[1:] == part.shape[1:]:
                groups[-1].append(part)
            else:
                groups.append([part])
        sizes = [sum(p.shape[0] for p in group) for group in groups]
        blocks = jnp.split(kernel, np.cumsum(sizes)[:-1])
        rows = [g[0] if len(g) == 1 else jnp.concatenate(g) for g in groups]
        y = _project(rows[0], blocks[0])
        for part, block in zip(rows[1:], blocks[1:], strict=True):
            y = y + _project(part, block)
        return y + bias.reshape(-1, *(1,) * (y.ndim - 1))


class LatentMLP(nn.Module):
    """[Dense, ReLU] x n_layers, then LayerNorm (torch's epsilon and two-pass variance), on
    feature-major inputs (`Dense`)."""

    width: int
    n_layers: int

    @nn.compact
    def __call__(self, *parts: jax.Array) -> jax.Array:
        """`parts`: the input as `Dense` takes it (its pieces, concatenated along the last axis)."""
        x = nn.relu(Dense(self.width, name="linear0")(*parts))
        for i in range(1, self.n_layers):
            x = nn.relu(Dense(self.width, name=f"linear{i}")(x))
        return nn.LayerNorm(
            epsilon=LAYER_NORM_EPS,
            use_fast_variance=False,
            reduction_axes=0,
            feature_axes=0,
            name="norm",
        )(x)


class GraphNetwork(nn.Module):
    """Encode-process-decode graph network with sum aggregation; see the torch twin. Inside,
    features are feature-major (`Dense`): (feature, node or edge, batch), so that gathering
    nodes onto edges and summing edges onto nodes move whole rows of the batch."""

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
        mlp = self.mlp_layers
        v = LatentMLP(self.node, mlp, name="enc_node")(features_first(nodes))
        e = LatentMLP(self.edge, mlp, name="enc_edge")(features_first(edges))
        u = LatentMLP(self.glob, mlp, name="enc_global")(features_first(glob))
        for k in range(self.steps):
            e = e + LatentMLP(self.edge, mlp, name=f"edge{k}")(
                e, v[:, senders], v[:, receivers], u[:, None]
            )
            agg = jnp.zeros((e.shape[0], *v.shape[1:]), e.dtype)
            agg = agg.at[:, senders].add(e).at[:, receivers].add(e)
            v = v + LatentMLP(self.node, mlp, name=f"node{k}")(v, agg, u[:, None])
            u = u + LatentMLP(self.glob, mlp, name=f"global{k}")(u, e.sum(1), v.sum(1))
        y = Dense(self.n_out, name="out")(LatentMLP(self.edge, mlp, name="dec")(e))
        return features_first(y)


def mirror_average(x: jnp.ndarray, f, signs: tuple | None) -> jnp.ndarray:
    """(f(x) + s_out f(s_in x)) / 2 in one batch (`architectures.mirror_signs`), f alone
    without signs: the twin of the torch models' MirrorAverage."""
    if signs is None:
        return f(x)
    n = x.shape[0]
    s_in, s_out = (jnp.asarray(s, x.dtype) for s in signs)
    y = f(jnp.concatenate([x, x * s_in]))
    return 0.5 * (y[:n] + y[n:] * s_out)

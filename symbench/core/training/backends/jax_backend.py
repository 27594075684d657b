"""JAX backend: `entry.build(dims, **hyper)` returns a `flax.linen.Module` whose
`__call__(**inputs)` maps normalized view inputs to normalized torques (N, n_legs, 3).

Training runs a whole epoch as one jitted `lax.scan` over batches (or, uncompiled, one
jitted call per batch); float64 predictions run under `jax.enable_x64`.

CPU computations run inline in the calling thread unless JAX_CPU_ENABLE_ASYNC_DISPATCH says
otherwise: handing a batch-1 prediction to a worker thread and waiting for it doubled the
control-loop latency on the shared 2-core machine (sdnn on hexa: 60 -> 32 us). Training, one
jitted scan per epoch, ran at the same rate both ways, measured alternately side by side
(sdnn 13.9-16.5k samples/s, before the change below). The setting takes effect when JAX
creates its CPU client, i.e. when this module is imported before any JAX computation.

Where a training step's time went (XLA profile, hexa, batch 64), and what changed it, each
measured side by side on one core in samples per CPU second: the kernels' gradients, dots
over the batch axis that XLA ran in Eigen at a third of YNNPACK's speed (45 % of sdnn's
step), go to YNNPACK; the transposed copies that took (13 % of sdnn's step, 15 % of the
graph networks') are gone with the models' feature-major layout (jax_models/layers.py's
`Dense`); Adam's loops over a graph network's many small arrays run over one vector
(`JaxTrainer`). Version 3 against version 2: ffnn 76.5k -> 79k, ffnn-leg 72k -> 75k,
sdgnn 28k -> 40k, sdnn 17.1k -> 17.6k, gnn 4.5k -> 6.7k. A batch-1 sdnn prediction (shared
2-core machine, loaded) costs about 5 us to call any jitted function, 2 to hand it numpy
inputs, 3 to fetch its output as float64 and some 33 us to run its 9 small dots (YNNPACK,
about 2 us each row-major since `layers._project`'s few-rows form, 4 before) and 2
matrix-vector products (Eigen) and some 36 tiny loops; no XLA option tried (Eigen, XNNPACK
or oneDNN dots; YNNPACK fusion types dot, eltwise and reduce and XNNPACK graph fusion, which
formed no other fusions here) made it faster.

Predictions and validation losses run the network on PREDICT_ROWS rows at a time (version 4):
one call of a whole evaluation set (4 096 rows) left every layer's activations out of the
cache. Rows predicted per second on one core (hexa, `bench models`' synthetic data), one call
against pieces of 256 rows: ffnn 57k -> 98k, sdnn 6.2k -> 24.5k, sdgnn 12.6k -> 45k, gnn 2.0k
-> 8.5k (64 to 512 rows a piece measured alike). A longer call runs as pieces of exactly
PREDICT_ROWS rows, the last one padded, so one compiled shape serves every evaluator and a
row comes out the same bits in any such call; XLA's products of another size round
otherwise, so a piece's rows differ from a whole call's in the last bits.
"""

from __future__ import annotations

import contextlib
import os
from collections.abc import Callable
from functools import partial
from typing import Any, NamedTuple

import flax.linen as nn
import jax
import jax.numpy as jnp
import numpy as np
import optax
from flax import traverse_util

from symbench.core.data.views.model_dims import ModelDims
from symbench.core.plugin.entries import ModelEntry
from symbench.core.training.backends.checks import build_error, check_output, check_params
from symbench.core.training.normalization import TARGET_KEY

if "JAX_CPU_ENABLE_ASYNC_DISPATCH" not in os.environ:
    jax.config.update("jax_cpu_enable_async_dispatch", False)

Params = dict[str, np.ndarray]
PREDICT_ROWS = 256  # rows per call of the network in predictions and validation (see top)
RAVEL_BELOW = 16384  # elements: smaller parameter arrays share one vector in Adam


def build_module(entry: ModelEntry, dims: ModelDims, hyper: dict[str, Any]) -> nn.Module:
    try:
        net = entry.build(dims, **hyper)
    except Exception as exc:
        raise build_error(entry, exc) from exc
    if not isinstance(net, nn.Module):
        raise build_error(
            entry, TypeError(f"build returned {type(net).__name__}, expected a flax.linen.Module")
        )
    return net


def _dummy(dims: ModelDims, dtype: Any = jnp.float32) -> dict[str, jax.Array]:
    return {k: jnp.zeros((1, *shape), dtype) for k, shape in dims.inputs}


def flatten(tree: Any) -> Params:
    """Copies: a zero-copy view of a device buffer would change when the next step donates it."""
    return {k: np.array(v) for k, v in traverse_util.flatten_dict(tree, sep="/").items()}


def unflatten(params: Params, dtype: Any = jnp.float32) -> dict:
    return traverse_util.unflatten_dict(
        {k: jnp.asarray(v, dtype) for k, v in params.items()}, sep="/"
    )


def checked_tree(entry, dims, net, params: Params, dtype: Any = jnp.float32) -> dict:
    shapes = jax.eval_shape(lambda: net.init(jax.random.PRNGKey(0), **_dummy(dims)))
    expected = {
        k: v.shape for k, v in traverse_util.flatten_dict(shapes["params"], sep="/").items()
    }
    check_params(entry, expected, params)
    return unflatten(params, dtype)


def check_output_shape(entry: ModelEntry, dims: ModelDims, net: nn.Module, params: Params) -> None:
    """The network's output shape for a batch of 2, from its trace alone (nothing is computed):
    the loss would broadcast (N, legs, 1) against (N, legs, 3) silently."""
    batch = {k: jax.ShapeDtypeStruct((2, *shape), jnp.float32) for k, shape in dims.inputs}
    try:
        out = jax.eval_shape(lambda p, b: net.apply({"params": p}, **b), unflatten(params), batch)
    except Exception as exc:
        raise build_error(entry, exc) from exc
    check_output(entry, dims, getattr(out, "shape", ()), 2)


def _x64(dtype: Any) -> contextlib.AbstractContextManager:
    return jax.enable_x64(True) if np.dtype(dtype) == np.float64 else contextlib.nullcontext()


class Trainable(NamedTuple):
    """The parameters as Adam sees them: arrays of `RAVEL_BELOW` elements or more as they
    are, the smaller ones raveled into one vector (see `JaxTrainer`)."""

    arrays: dict[str, jax.Array]
    vector: jax.Array


class Raveling:
    """Which parameter arrays `Trainable.vector` holds, in which order and shape, and the
    conversions: on the host with numpy (a jitted or eager JAX conversion would compile for
    every array shape, seconds a training), traced inside the jitted step."""

    def __init__(self, shapes: dict[str, tuple[int, ...]]):
        self.shapes = {k: shapes[k] for k in sorted(shapes) if np.prod(shapes[k]) < RAVEL_BELOW}
        self.bounds = np.cumsum([int(np.prod(s)) for s in self.shapes.values()])[:-1].tolist()

    def trainable(self, flat: Params) -> Trainable:
        arrays = {k: jnp.asarray(v, jnp.float32) for k, v in flat.items() if k not in self.shapes}
        parts = [np.asarray(flat[k], np.float32).ravel() for k in self.shapes]
        return Trainable(arrays, jnp.asarray(np.concatenate([np.zeros(0, np.float32), *parts])))

    def flat(self, p: Trainable) -> Params:
        """The arrays by name, as numpy copies."""
        parts = np.split(np.array(p.vector), self.bounds) if self.shapes else []
        small = {k: a.reshape(s) for (k, s), a in zip(self.shapes.items(), parts, strict=True)}
        return {**{k: np.array(v) for k, v in p.arrays.items()}, **small}

    def tree(self, p: Trainable) -> dict:
        """The network's nested parameters, inside a jitted function."""
        parts = jnp.split(p.vector, self.bounds) if self.shapes else []
        small = {k: a.reshape(s) for (k, s), a in zip(self.shapes.items(), parts, strict=True)}
        return traverse_util.unflatten_dict({**p.arrays, **small}, sep="/")


class JaxTrainer:
    """Adam on the small parameter arrays raveled into one vector (`Trainable`): XLA runs
    Adam's update as a few loops per array, each costing microseconds before any work, and
    a graph network has 116 arrays (sdgnn 56), most of them biases, norms and kernels of
    16 x 16 (measured: gnn +10 %, sdgnn +14 % samples per second); large kernels stay
    arrays, whose copy out of a vector would cost more than their loops (ffnn -12 % with
    every array raveled). Checkpoints keep the per-array layout (`params`,
    `optimizer_state`)."""

    def __init__(
        self,
        net: nn.Module,
        to_tree: Callable[[Params], dict],
        params: Params,
        learning_rate: float,
        compiled: bool,
    ):
        self.to_tree = to_tree
        self.tx = optax.adam(learning_rate)  # each step's update then times its rate scale
        self.raveling = Raveling({k: np.shape(v) for k, v in params.items()})
        trainable = self._trainable(params)
        self.state = (trainable, self.tx.init(trainable))
        tree = self.raveling.tree

        def loss_fn(p, inputs, target):
            out = net.apply({"params": tree(p)}, **inputs)
            return jnp.mean((out - target) ** 2)

        def step(state, idx_scale, inputs, target):
            (p, opt_state), (idx, scale) = state, idx_scale
            batch = {k: v[idx] for k, v in inputs.items()}
            loss, grads = jax.value_and_grad(loss_fn)(p, batch, target[idx])
            updates, opt_state = self.tx.update(grads, opt_state, p)
            updates = jax.tree_util.tree_map(lambda u: u * scale, updates)
            return (optax.apply_updates(p, updates), opt_state), loss

        def epoch(state, inputs, target, order, scales):
            state, losses = jax.lax.scan(
                lambda s, i: step(s, i, inputs, target), state, (order, scales)
            )
            return state, losses.mean()

        def sse(p, inputs, target, idx, weight):
            batch = {k: v[idx] for k, v in inputs.items()}
            err = net.apply({"params": tree(p)}, **batch) - target[idx]
            return jnp.sum(weight[:, None, None] * err.astype(jnp.float32) ** 2)

        self._epoch = jax.jit(epoch, donate_argnums=0) if compiled else None
        self._step = jax.jit(step, donate_argnums=0)
        self._sse = jax.jit(sse)

    def _trainable(self, params: Params) -> Trainable:
        """`params` checked against the network (names, shapes), as Adam sees them."""
        self.to_tree(params)
        return self.raveling.trainable(params)

    def set_data(self, train_inputs, train_target, val_inputs, val_target) -> None:
        def arrays(d):
            return {k: jnp.asarray(v, jnp.float32) for k, v in d.items()}

        self.train = (arrays(train_inputs), jnp.asarray(train_target, jnp.float32))
        self.val = (arrays(val_inputs), jnp.asarray(val_target, jnp.float32))

    def train_epoch(self, order: np.ndarray, rate_scale: np.ndarray | None = None) -> float:
        ones = np.ones(len(order), np.float32)
        scales = jnp.asarray(ones if rate_scale is None else rate_scale, jnp.float32)
        if self._epoch is not None:
            self.state, loss = self._epoch(self.state, *self.train, jnp.asarray(order), scales)
            return float(loss)
        losses = []
        for idx, scale in zip(order, scales, strict=True):
            self.state, loss = self._step(self.state, (jnp.asarray(idx), scale), *self.train)
            losses.append(loss)
        return float(jnp.mean(jnp.stack(losses)))

    def val_loss(self) -> float:
        inputs, target = self.val
        n = len(target)
        chunk = min(n, PREDICT_ROWS)
        total = 0.0
        for start in range(0, n, chunk):
            idx = np.arange(start, start + chunk)
            weight = (idx < n).astype(np.float32)
            total += float(
                self._sse(self.state[0], inputs, target, jnp.asarray(idx % n), jnp.asarray(weight))
            )
        return total / target.size

    def params(self) -> Params:
        return self.raveling.flat(self.state[0])

    def load_params(self, params: Params) -> None:
        self.state = (self._trainable(params), self.state[1])

    def _per_array(self, opt_state: Any) -> Any:
        """Adam's state with each `Trainable` (its moments) as the network's nested arrays
        (numpy): the layout of checkpoints."""
        return jax.tree_util.tree_map(
            lambda x: (
                traverse_util.unflatten_dict(self.raveling.flat(x), sep="/")
                if isinstance(x, Trainable)
                else x
            ),
            opt_state,
            is_leaf=lambda x: isinstance(x, Trainable),
        )

    def optimizer_state(self) -> Params:
        leaves = jax.tree_util.tree_flatten_with_path(self._per_array(self.state[1]))[0]
        return {jax.tree_util.keystr(path): np.array(v) for path, v in leaves}

    def load_optimizer_state(self, state: Params) -> None:
        paths, treedef = jax.tree_util.tree_flatten_with_path(self._per_array(self.state[1]))
        leaves = [np.asarray(state[jax.tree_util.keystr(path)]) for path, _ in paths]
        per_array = jax.tree_util.tree_unflatten(treedef, leaves)
        self.state = (
            self.state[0],
            jax.tree_util.tree_map(
                lambda own, arrays: (
                    self.raveling.trainable(traverse_util.flatten_dict(arrays, sep="/"))
                    if isinstance(own, Trainable)
                    else jnp.asarray(arrays)
                ),
                self.state[1],
                per_array,
                is_leaf=lambda x: isinstance(x, Trainable),
            ),
        )


def _pieces(xs: list[np.ndarray]) -> list[tuple[int, list[np.ndarray]]]:
    """A call's inputs as (rows, arrays) pieces: a call of at most PREDICT_ROWS rows as it is
    (a control loop's batch-1 call keeps its own compiled shape), a longer one as pieces of
    exactly PREDICT_ROWS rows, the last one padded with copies of its last row, so that one
    compiled shape serves every call and a row's prediction is the same bits in any call
    longer than a piece."""
    n = len(xs[0])
    if n <= PREDICT_ROWS:
        return [(n, xs)]
    starts = range(0, n, PREDICT_ROWS)
    return [
        (min(PREDICT_ROWS, n - s), [_padded(x[s : s + PREDICT_ROWS]) for x in xs]) for s in starts
    ]


def _padded(rows: np.ndarray) -> np.ndarray:
    """`rows` with copies of its last row appended up to PREDICT_ROWS rows."""
    pad = [(0, PREDICT_ROWS - len(rows))] + [(0, 0)] * (rows.ndim - 1)
    return np.pad(rows, pad, mode="edge")


class JaxBackend:
    name = "jax"
    default_compiled = True  # jit pays for itself after a call or two

    def init_params(self, entry, dims, hyper, seed) -> Params:
        net = build_module(entry, dims, hyper)
        init = jax.jit(net.init)  # op-by-op initialization is several times slower
        return flatten(init(jax.random.PRNGKey(seed), **_dummy(dims))["params"])

    def parameter_shapes(self, entry, dims, hyper) -> dict[str, tuple[int, ...]]:
        net = build_module(entry, dims, hyper)
        tree = jax.eval_shape(net.init, jax.random.PRNGKey(0), **_dummy(dims))["params"]
        flat = traverse_util.flatten_dict(tree, sep="/")
        return {k: tuple(v.shape) for k, v in flat.items()}

    def make_predictor(
        self, entry, dims, hyper, params, normalizer, dtype=np.float32, compiled=True
    ):
        net = build_module(entry, dims, hyper)
        keys = dims.keys
        with _x64(dtype):
            tree = checked_tree(entry, dims, net, params, dtype)
            stats = {
                k: tuple(jnp.asarray(a, dtype) for a in normalizer.stats[k])
                for k in (*keys, TARGET_KEY)
            }

        def forward(p, stats, *xs):
            inputs = {k: (x - stats[k][0]) / stats[k][1] for k, x in zip(keys, xs)}
            y = net.apply({"params": p}, **inputs)
            return y * stats[TARGET_KEY][1] + stats[TARGET_KEY][0]

        # jit closes over parameters and statistics: constants cost nothing per call
        run = jax.jit(partial(forward, tree, stats)) if compiled else partial(forward, tree, stats)

        def predict(inputs: dict[str, np.ndarray]) -> np.ndarray:
            xs = [np.asarray(inputs[k], dtype) for k in keys]
            pieces = []
            with _x64(dtype):
                for rows, piece in _pieces(xs):
                    y = np.asarray(run(*piece))
                    check_output(entry, dims, y.shape, len(piece[0]))
                    pieces.append(y[:rows])
            joined = pieces[0] if len(pieces) == 1 else np.concatenate(pieces)
            return joined.astype(np.float64)

        return predict

    def make_trainer(self, entry, dims, hyper, params, learning_rate, compiled=True):
        net = build_module(entry, dims, hyper)
        check_output_shape(entry, dims, net, params)
        return JaxTrainer(
            net, lambda p: checked_tree(entry, dims, net, p), params, learning_rate, compiled
        )


BACKEND = JaxBackend()

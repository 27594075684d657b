"""How close a training step comes to the CPU's limit: the model's own FLOPs per sample and
each backend's dense-matmul rate, the best of which is the limit (see `bench.models`).

A samples/s figure alone says nothing about headroom; samples/s x FLOPs per sample over the
best matmul rate measured in the same process does (1.0 would be a step made of nothing but
large matmuls running at the best BLAS's best). FLOPs are counted the usual way, 2 per multiply-add:
torch's FlopCounterMode counts matmuls and convolutions of the forward and backward pass;
XLA's cost analysis of the jitted gradient counts every operation. The two agree closely for
these networks, whose FLOPs are almost all matmuls.
"""

from __future__ import annotations

import time
from typing import Any

import numpy as np

from symbench.core.data.views.model_dims import ModelDims
from symbench.core.plugin.entries import ModelEntry

MATMUL_SIZE = 512  # large enough for the BLAS's peak on one core, small enough for seconds
WINDOW_S = 0.1  # timing window of `best_rate`


def step_flops_per_sample(entry: ModelEntry, dims: ModelDims, batch: int) -> float:
    """FLOPs of one training step's forward and backward pass, per sample."""
    counter = _torch_step_flops if entry.backend == "torch" else _jax_step_flops
    return counter(entry, dims, batch) / batch


def matmul_flops_per_s(backend: str, seconds: float) -> float:
    """The backend's float32 dense-matmul rate (MATMUL_SIZE squared) with its thread setting."""
    return _torch_matmul_rate(seconds) if backend == "torch" else _jax_matmul_rate(seconds)


def _inputs(dims: ModelDims, batch: int) -> dict[str, np.ndarray]:
    rng = np.random.default_rng(0)
    return {k: rng.normal(size=(batch, *shape)).astype(np.float32) for k, shape in dims.inputs}


def _target(dims: ModelDims, batch: int) -> np.ndarray:
    return np.zeros((batch, dims.n_legs, 3), np.float32)


def _torch_step_flops(entry: ModelEntry, dims: ModelDims, batch: int) -> float:
    import torch
    from torch.utils.flop_counter import FlopCounterMode

    from symbench.core.training.backends.torch_backend import build_network

    net = build_network(entry, dims, {})
    inputs = {k: torch.from_numpy(v) for k, v in _inputs(dims, batch).items()}
    target = torch.from_numpy(_target(dims, batch))
    with FlopCounterMode(display=False) as counter:
        loss = torch.nn.functional.mse_loss(net(**inputs), target)
        loss.backward()
    return float(counter.get_total_flops())


def _jax_step_flops(entry: ModelEntry, dims: ModelDims, batch: int) -> float:
    import jax
    import jax.numpy as jnp

    from symbench.core.training.backends.jax_backend import build_module

    net = build_module(entry, dims, {})
    inputs: dict[str, Any] = {k: jnp.asarray(v) for k, v in _inputs(dims, batch).items()}
    params = net.init(jax.random.PRNGKey(0), **inputs)["params"]
    target = jnp.asarray(_target(dims, batch))

    def loss(p: Any) -> Any:
        out: Any = net.apply({"params": p}, **inputs)
        return jnp.mean((out - target) ** 2)

    cost: Any = jax.jit(jax.grad(loss)).lower(params).compile().cost_analysis()
    cost = cost[0] if isinstance(cost, list) else cost  # a list of one dict on older JAX
    return float(cost["flops"])


def best_rate(run: Any, per_call: float, seconds: float) -> float:
    """`per_call` x calls of `run()` per second, the best of 0.1 s windows over `seconds`
    (at least one), after one warm-up call (thread pools, JIT): on a machine shared with
    other work, the rate of the least disturbed window."""
    run()
    best, end = 0.0, time.perf_counter() + seconds
    while True:
        start, n = time.perf_counter(), 0
        while time.perf_counter() - start < WINDOW_S:
            run()
            n += 1
        best = max(best, n * per_call / (time.perf_counter() - start))
        if time.perf_counter() >= end:
            return best


def _torch_matmul_rate(seconds: float) -> float:
    import torch

    import symbench.core.training.backends.torch_backend  # noqa: F401  (its thread setting)

    a = torch.randn(MATMUL_SIZE, MATMUL_SIZE)
    return best_rate(lambda: torch.mm(a, a), 2.0 * MATMUL_SIZE**3, seconds)


def _jax_matmul_rate(seconds: float) -> float:
    import jax
    import jax.numpy as jnp

    import symbench.core.training.backends.jax_backend  # noqa: F401  (its dispatch setting)

    a = jnp.asarray(np.random.default_rng(0).normal(size=(MATMUL_SIZE,) * 2), jnp.float32)
    mm = jax.jit(jnp.dot)
    return best_rate(lambda: mm(a, a).block_until_ready(), 2.0 * MATMUL_SIZE**3, seconds)

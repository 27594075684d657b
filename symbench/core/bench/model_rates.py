"""The figures of one thread setting of `symbench bench models`, taken in the process that
`threads.confine` confined: every row (training rate, inference latency, FLOPs) and both
backends' dense-matmul rates, so that each row's share of the best matmul rate compares
figures computed with the same cores.

Every torch figure comes before JAX loads (XLA's idle CPU threads would compete with
torch's); both matmul rates are measured whichever backends the rows use, since the
denominator is the best either backend reaches.
"""

from __future__ import annotations

import os
import statistics
import time
from collections.abc import Callable
from typing import Any

import numpy as np

from symbench.core.bench.flops import (
    MATMUL_SIZE,
    best_rate,
    matmul_flops_per_s,
    step_flops_per_sample,
)
from symbench.core.bench.threads import XLA_POOL_THREAD, threads_named
from symbench.core.config.presets import SMALL
from symbench.core.data.views.model_dims import dims_of
from symbench.core.plugin import registry
from symbench.core.plugin.entries import BACKENDS
from symbench.core.training.backends import get_backend
from symbench.core.training.kernels import ENV_PINS
from symbench.core.training.normalization import Normalizer
from symbench.core.training.onnx_export import onnx_bytes, onnx_predictor

BATCH = 64
# the closed loop's call on `small`: every reference at every PD fraction in one batch
LOCKSTEP = SMALL.closed_loop.references * len(SMALL.closed_loop.pd_fractions)
# an evaluator's call: the test rows of the transform-based evaluators (the synthetic views
# of `measure_setting` hold exactly this many)
EVAL_ROWS = SMALL.evaluation.max_samples
CALL_STEPS = 16  # training steps per timed call (gnn in torch: about 0.2 s)

Say = Callable[[str], None]


def train_rate(entry, views, compiled: bool, seconds: float) -> float:
    """Samples per second of the training step at batch 64, estimated as the matmul rate is
    (`flops.best_rate`: the best of short windows), so that on a machine shared with other
    work the two are compared alike: a mean over the whole time would count the other work
    against training only. The first call compiles."""
    data = views[entry.view]
    backend = get_backend(entry.backend)
    dims = dims_of(data)
    trainer = backend.make_trainer(
        entry, dims, {}, backend.init_params(entry, dims, {}, 0), entry.learning_rate, compiled
    )
    trainer.set_data(data.inputs, data.target, data.inputs, data.target)
    order = np.arange(CALL_STEPS * BATCH).reshape(CALL_STEPS, BATCH)
    return best_rate(lambda: trainer.train_epoch(order), order.size, seconds)


def latency_us(entry, views, mode: str, seconds: float, batch: int = 1, calls: int = 50) -> float:
    """Median wall time of one prediction of `batch` rows (normalization included),
    microseconds, over `seconds` and at least `calls` calls; `mode` plain or compiled (the
    backend's predictor), or onnx (the model exported as `symbench export --batch BATCH`
    writes it, run by ONNX Runtime on one thread)."""
    data = views[entry.view]
    dims = dims_of(data)
    backend = get_backend(entry.backend)
    params, normalizer = backend.init_params(entry, dims, {}, 0), Normalizer.fit(data)
    if mode == "onnx":
        exported = onnx_bytes(entry, dims, {}, params, normalizer, batch=batch)
        predict = onnx_predictor(exported, dims.keys)
    else:
        compiled = mode == "compiled"
        predict = backend.make_predictor(entry, dims, {}, params, normalizer, np.float32, compiled)
    rows = {k: v[:batch].astype(np.float32) for k, v in data.inputs.items()}
    for _ in range(min(20, calls)):
        predict(rows)
    times: list[float] = []
    start = time.perf_counter()
    while time.perf_counter() - start < seconds or len(times) < calls:
        t = time.perf_counter()
        predict(rows)
        times.append(time.perf_counter() - t)
    return 1e6 * statistics.median(times)


def measure(
    entry, views, seconds: float, modes: tuple[bool, ...], latency: bool, say: Say
) -> dict[str, Any]:
    """One row: training rate (and, with `latency`, the latency of a batch-1 call and of the
    closed loop's lockstep call, and the rows per second of an evaluator's call) in each
    mode, and the FLOPs per second of training in its best mode."""
    row: dict[str, Any] = {"model": entry.name, "backend": entry.backend}
    names = ["compiled" if c else "plain" for c in modes]
    for compiled, mode in zip(modes, names):
        say(f"training, {mode}")
        row[f"train_samples_per_s_{mode}"] = train_rate(entry, views, compiled, seconds)
    row["train_best"] = max(names, key=lambda m: row[f"train_samples_per_s_{m}"])
    if latency:
        inference = [*names, *(["onnx"] if entry.backend == "torch" else [])]
        for mode in inference:
            say(f"batch-1 inference, {mode}")
            row[f"infer_batch1_us_{mode}"] = latency_us(entry, views, mode, seconds)
            say(f"lockstep inference ({LOCKSTEP} rows), {mode}")
            row[f"infer_lockstep_us_{mode}"] = latency_us(entry, views, mode, seconds, LOCKSTEP)
        for mode in names:  # evaluators call the backend's predictor, never ONNX Runtime
            say(f"evaluation predictions ({EVAL_ROWS} rows), {mode}")
            call_us = latency_us(entry, views, mode, seconds, EVAL_ROWS, calls=3)
            row[f"predict_rows_per_s_{mode}"] = EVAL_ROWS / (1e-6 * call_us)
        row["infer_best"] = min(inference, key=lambda m: row[f"infer_batch1_us_{m}"])
        row["lockstep_best"] = min(inference, key=lambda m: row[f"infer_lockstep_us_{m}"])
    say("counting FLOPs")
    flops = step_flops_per_sample(entry, dims_of(views[entry.view]), BATCH)
    row["train_flops_per_sample"] = flops
    row["train_flops_per_s"] = flops * row[f"train_samples_per_s_{row['train_best']}"]
    return row


def measure_setting(job: dict[str, Any], cores: list[int], say: Say) -> dict[str, Any]:
    """Every row of `job` and both matmul rates, then each row's share of the best of them
    (and of its own backend's); the threads each backend used and the kernel pins in force."""
    from symbench.core.robot.specs import load_robot
    from symbench.testing.synthetic import synthetic_views

    started = time.perf_counter()
    views = synthetic_views(load_robot(job["robot"]).n_legs, EVAL_ROWS, seed=0)
    entries = [
        registry.model(n, b) for b in BACKENDS for n in job["models"] if b in job["backends"]
    ]
    rows: list[dict[str, Any]] = []
    matmul: dict[str, float] = {}
    threads: dict[str, int] = {}
    for backend in BACKENDS:
        # the best of a short window before each row and a whole one after the last: one
        # window alone can fall into a moment when other work holds the cores
        rates = []
        for entry in (e for e in entries if e.backend == backend):
            rates.append(matmul_flops_per_s(backend, job["seconds"] / 4))
            both = job["modes"] == "both"
            modes = (False, True) if both else (get_backend(backend).default_compiled,)
            prefix = f"[{len(rows) + 1}/{len(entries)}] {entry.name}/{backend}"
            say_row = _timed(say, prefix, started)
            rows.append(measure(entry, views, job["seconds"], modes, job["latency"], say_row))
        say(f"{backend}: dense matmul rate ({MATMUL_SIZE}x{MATMUL_SIZE}, float32)")
        matmul[backend] = max([*rates, matmul_flops_per_s(backend, job["seconds"])])
        threads[backend] = _threads_used(backend)
    best = max(matmul, key=matmul.__getitem__)
    for row in rows:
        row["share_of_best_matmul"] = row["train_flops_per_s"] / matmul[best]
        row["share_of_own_matmul"] = row["train_flops_per_s"] / matmul[row["backend"]]
    return {
        "threads": len(cores),
        "cores": cores,
        "threads_used": threads,
        "matmul_flops_per_s": matmul,
        "best_matmul_backend": best,
        "latency_measured": job["latency"],
        "kernel_pins": _kernel_pins(),
        "seconds": round(time.perf_counter() - started, 1),
        "rows": rows,
    }


def _timed(say: Say, prefix: str, started: float) -> Say:
    """`say` with a row's prefix and the seconds since the setting started."""
    return lambda what: say(f"{prefix}: {what} ({time.perf_counter() - started:.0f} s)")


def _threads_used(backend: str) -> int:
    """torch's intra-op threads; the threads of XLA's compute pool, pinned for training
    (`kernels.XLA_POOL`; counted after the matmul, so the pool exists)."""
    if backend == "torch":
        import torch

        return torch.get_num_threads()
    return threads_named(XLA_POOL_THREAD)


def _kernel_pins() -> dict[str, str | None]:
    """The training kernel pins (`symbench.core.training.kernels`) as this process has them,
    and the kernels torch's own loops run."""
    import torch

    pins: dict[str, str | None] = {name: os.environ.get(name) for name in ENV_PINS}
    pins["XLA_FLAGS"] = os.environ.get("XLA_FLAGS")
    pins["torch_cpu_capability"] = torch.backends.cpu.get_cpu_capability()
    return pins

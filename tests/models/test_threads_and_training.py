"""Training gives the same numbers on every core count. XLA compiles a training step by the
size of its CPU thread pool (one thread: no loop split across threads, other fusions), so
symbench pins the pool (`kernels.XLA_POOL`) whatever the machine or the caller says; torch
trains on one thread (the torch backend's default)."""

from __future__ import annotations

import os
import subprocess
import sys

from symbench.core.training.kernels import XLA_POOL

# trains hexa's sdnn in the backend argv[2] for a few steps on synthetic data and prints its
# parameters' digest and the size of XLA's pool; argv[1]: the cores to confine it to, first
CHILD = """
import hashlib, os, sys
os.sched_setaffinity(0, [int(c) for c in sys.argv[1].split(",")])
import numpy as np
import symbench
from symbench.core.bench.threads import XLA_POOL_THREAD, threads_named
from symbench.core.data.views.model_dims import dims_of
from symbench.core.plugin import registry
from symbench.core.training.backends import get_backend
from symbench.testing.synthetic import synthetic_views

entry, backend = registry.model("sdnn", sys.argv[2]), get_backend(sys.argv[2])
data = synthetic_views(6, 256, seed=0)[entry.view]
dims = dims_of(data)
params = backend.init_params(entry, dims, {}, 0)
compiled = backend.default_compiled
trainer = backend.make_trainer(entry, dims, {}, params, entry.learning_rate, compiled)
trainer.set_data(data.inputs, data.target, data.inputs, data.target)
for _ in range(2):
    trainer.train_epoch(np.arange(256).reshape(4, 64))
digest = hashlib.sha256()
for _, value in sorted(trainer.params().items()):
    digest.update(np.ascontiguousarray(value).tobytes())
print(digest.hexdigest(), threads_named(XLA_POOL_THREAD))
"""


def _trained(backend: str, runs: list[tuple[list[int], dict[str, str]]]) -> list[tuple[str, int]]:
    """(digest, XLA pool threads) of a child per (cores, environment), the children at once."""
    children = [
        subprocess.Popen(
            [sys.executable, "-c", CHILD, ",".join(map(str, cores)), backend],
            env=env,
            stdout=subprocess.PIPE,
            stderr=subprocess.PIPE,
            text=True,
        )
        for cores, env in runs
    ]
    results = []
    for child in children:
        out, err = child.communicate(timeout=300)
        assert child.returncode == 0, err
        digest, pool = out.split()
        results.append((digest, int(pool)))
    return results


def test_jax_training_is_the_same_on_one_core_and_under_a_callers_thread_count():
    """Unpinned, the process on one core trains with a one-thread pool and the one told
    NPROC=4 with four: sdnn's parameters differ after eight steps. Pinned, both pools have
    the pinned size and the parameters agree to the last bit."""
    cores = sorted(os.sched_getaffinity(0))
    env = {k: v for k, v in os.environ.items() if k != "NPROC"}
    one_core, told_four = _trained("jax", [(cores[:1], env), (cores, {**env, "NPROC": "4"})])
    pinned = int(XLA_POOL["NPROC"])
    assert one_core[1] == told_four[1] == pinned
    assert one_core[0] == told_four[0]


def test_torch_training_is_the_same_on_one_core_and_on_every_core():
    """Torch's one thread whatever the cores or a caller's OpenMP and MKL settings say (more
    threads would split its sums)."""
    cores = sorted(os.sched_getaffinity(0))
    env = {k: v for k, v in os.environ.items() if k != "SYMBENCH_TORCH_THREADS"}
    told_four = {**env, "OMP_NUM_THREADS": "4", "MKL_NUM_THREADS": "4"}
    one_core, every_core = _trained("torch", [(cores[:1], env), (cores, told_four)])
    assert one_core[0] == every_core[0]


def test_a_pool_size_changed_after_import_is_named_as_a_problem(monkeypatch):
    """`verify` warns through this list: a caller that changed NPROC after importing
    symbench trains JAX steps compiled for another pool."""
    from symbench.core.training.kernels import training_kernel_problems

    assert not any("NPROC" in p for p in training_kernel_problems())
    monkeypatch.setenv("NPROC", "1")
    assert "NPROC is '1', not '2'" in training_kernel_problems()

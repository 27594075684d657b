"""`symbench bench models`: training throughput (batch 64) and batch-1 inference latency.

Every model in both backends, on synthetic data shaped like the robot's, each measured
uncompiled and compiled (torch.compile; JAX: one jitted call per step vs one jitted scan
per epoch for training, eager vs jit for inference), so the table shows which wins.
"""

from __future__ import annotations

import json
import statistics
import time
from typing import Any

import click
import numpy as np
from rich.console import Console
from rich.table import Table

from symbench.core.common.cli_types import POSITIVE
from symbench.core.data.model_dims import dims_of
from symbench.core.plugin import registry
from symbench.core.plugin.entries import BACKENDS
from symbench.core.training.backends import get_backend
from symbench.core.training.normalization import Normalizer

BATCH = 64


def train_rate(entry, views, compiled: bool, seconds: float) -> float:
    """Samples per second of the training step at batch 64, after a warm-up epoch."""
    data = views[entry.view]
    backend = get_backend(entry.backend)
    dims = dims_of(data)
    trainer = backend.make_trainer(
        entry, dims, {}, backend.init_params(entry, dims, {}, 0), entry.learning_rate, compiled
    )
    trainer.set_data(data.inputs, data.target, data.inputs, data.target)
    n_batches = len(data) // BATCH
    order = np.arange(n_batches * BATCH).reshape(n_batches, BATCH)
    trainer.train_epoch(order)  # compiles
    done, start = 0, time.perf_counter()
    while time.perf_counter() - start < seconds:
        trainer.train_epoch(order)
        done += n_batches * BATCH
    return done / (time.perf_counter() - start)


def latency_us(entry, views, compiled: bool, seconds: float) -> float:
    """Median wall time of one batch-1 prediction (normalization included), microseconds."""
    data = views[entry.view]
    backend = get_backend(entry.backend)
    dims = dims_of(data)
    predict = backend.make_predictor(
        entry,
        dims,
        {},
        backend.init_params(entry, dims, {}, 0),
        Normalizer.fit(data),
        np.float32,
        compiled,
    )
    one = {k: v[:1].astype(np.float32) for k, v in data.inputs.items()}
    for _ in range(20):
        predict(one)
    times: list[float] = []
    start = time.perf_counter()
    while time.perf_counter() - start < seconds or len(times) < 50:
        t = time.perf_counter()
        predict(one)
        times.append(time.perf_counter() - t)
    return 1e6 * statistics.median(times)


def measure(entry, views, seconds: float) -> dict[str, Any]:
    row: dict[str, Any] = {"model": entry.name, "backend": entry.backend}
    for compiled in (False, True):
        mode = "compiled" if compiled else "plain"
        row[f"train_samples_per_s_{mode}"] = train_rate(entry, views, compiled, seconds)
        row[f"infer_batch1_us_{mode}"] = latency_us(entry, views, compiled, seconds)
    row["train_best"] = max(("plain", "compiled"), key=lambda m: row[f"train_samples_per_s_{m}"])
    row["infer_best"] = min(("plain", "compiled"), key=lambda m: row[f"infer_batch1_us_{m}"])
    return row


@click.command("models")
@click.option("--robot", "robot_name", default="hexa", show_default=True)
@click.option(
    "--models",
    "names",
    default="ffnn,ffnn-leg,gnn,sdgnn,sdnn",
    show_default=True,
    help="Comma-separated model names.",
)
@click.option("--backends", default=",".join(BACKENDS), show_default=True)
@click.option(
    "--seconds", default=2.0, show_default=True, type=POSITIVE, help="Timing window per figure."
)
@click.option("--json", "as_json", is_flag=True, help="Print JSON instead of a table.")
def bench_models(robot_name: str, names: str, backends: str, seconds: float, as_json: bool) -> None:
    """Training samples/s (batch 64) and batch-1 inference latency per model and backend."""
    import os

    from symbench.core.robot.specs import load_robot
    from symbench.testing.synthetic import synthetic_views

    robot = load_robot(robot_name)
    # every torch figure before JAX starts: XLA's idle CPU threads would compete with torch's
    entries = [
        registry.model(n.strip(), b.strip()) for b in backends.split(",") for n in names.split(",")
    ]
    views = synthetic_views(robot.n_legs, 64 * BATCH, seed=0)
    rows = [measure(e, views, seconds) for e in entries]
    report = {
        "robot": robot_name,
        "batch": BATCH,
        "cpu_count": os.cpu_count(),
        "seconds_per_figure": seconds,
        "rows": rows,
    }
    if as_json:
        click.echo(json.dumps(report, indent=2))
        return
    table = Table(title=f"symbench bench models ({robot_name}, {os.cpu_count()} CPUs)")
    for col in (
        "model",
        "backend",
        "train/s plain",
        "train/s compiled",
        "infer us plain",
        "infer us compiled",
    ):
        table.add_column(col, justify="right")
    for r in rows:
        table.add_row(
            r["model"],
            r["backend"],
            *(
                _mark(f"{r[f'train_samples_per_s_{m}']:,.0f}", r["train_best"] == m)
                for m in ("plain", "compiled")
            ),
            *(
                _mark(f"{r[f'infer_batch1_us_{m}']:.1f}", r["infer_best"] == m)
                for m in ("plain", "compiled")
            ),
        )
    Console().print(table)


def _mark(text: str, best: bool) -> str:
    return f"[bold green]{text}[/]" if best else text

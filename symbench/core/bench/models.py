"""`symbench bench models`: training throughput (batch 64), how close it comes to the CPU's
matmul limit, and batch-1 inference latency.

Every model in both backends, on synthetic data shaped like the robot's, in each backend's
default mode, or (`--modes both`) uncompiled and compiled side by side (torch.compile; JAX:
one jitted call per step vs one jitted scan per epoch for training, eager vs jit for
inference), so the table shows which wins.
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

from symbench.core.bench.flops import MATMUL_SIZE, matmul_flops_per_s, step_flops_per_sample
from symbench.core.common.cli_types import POSITIVE
from symbench.core.common.console import StdoutConsole
from symbench.core.data.views.model_dims import dims_of
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


def measure(entry, views, seconds: float, modes: tuple[bool, ...], say) -> dict[str, Any]:
    """One row: training rate and latency in each mode, and how close training comes to the
    backend's matmul limit (its best mode's samples/s x FLOPs per sample / matmul rate)."""
    row: dict[str, Any] = {"model": entry.name, "backend": entry.backend}
    for compiled in modes:
        mode = "compiled" if compiled else "plain"
        say(f"training, {mode}")
        row[f"train_samples_per_s_{mode}"] = train_rate(entry, views, compiled, seconds)
        say(f"batch-1 inference, {mode}")
        row[f"infer_batch1_us_{mode}"] = latency_us(entry, views, compiled, seconds)
    names = ["compiled" if c else "plain" for c in modes]
    row["train_best"] = max(names, key=lambda m: row[f"train_samples_per_s_{m}"])
    row["infer_best"] = min(names, key=lambda m: row[f"infer_batch1_us_{m}"])
    say("counting FLOPs")
    flops = step_flops_per_sample(entry, dims_of(views[entry.view]), BATCH)
    row["train_flops_per_sample"] = flops
    row["train_flops_per_s"] = flops * row[f"train_samples_per_s_{row['train_best']}"]
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
    "--modes",
    type=click.Choice(["default", "both"]),
    default="default",
    show_default=True,
    help="default: each backend's own choice (JAX compiled, torch plain); both: plain and "
    "compiled side by side (torch.compile adds tens of seconds per model).",
)
@click.option(
    "--seconds", default=1.0, show_default=True, type=POSITIVE, help="Timing window per figure."
)
@click.option("--json", "as_json", is_flag=True, help="Print JSON instead of a table.")
def bench_models(
    robot_name: str, names: str, backends: str, modes: str, seconds: float, as_json: bool
) -> None:
    """Training samples/s (batch 64), the fraction of the CPU's matmul rate that training
    reaches, and batch-1 inference latency, per model and backend. Progress goes to stderr."""
    import os

    from symbench.core.robot.specs import load_robot
    from symbench.testing.synthetic import synthetic_views

    robot = load_robot(robot_name)
    # every torch figure before JAX starts: XLA's idle CPU threads would compete with torch's
    entries = [
        registry.model(n.strip(), b.strip()) for b in backends.split(",") for n in names.split(",")
    ]
    views = synthetic_views(robot.n_legs, 64 * BATCH, seed=0)
    progress = Console(stderr=True)
    started = time.perf_counter()
    rows = []
    for i, entry in enumerate(entries, start=1):

        def say(what: str, i: int = i, entry=entry) -> None:
            elapsed = time.perf_counter() - started
            progress.print(
                f"[{i}/{len(entries)}] {entry.name}/{entry.backend}: {what} ({elapsed:.0f} s)"
            )

        backend_modes = (
            (False, True) if modes == "both" else (get_backend(entry.backend).default_compiled,)
        )
        rows.append(measure(entry, views, seconds, backend_modes, say))
    matmul = {}
    for backend in sorted({r["backend"] for r in rows}):
        progress.print(f"{backend}: dense matmul rate ({MATMUL_SIZE}x{MATMUL_SIZE}, float32)")
        matmul[backend] = matmul_flops_per_s(backend, seconds)
    for r in rows:
        r["matmul_flops_per_s"] = matmul[r["backend"]]
        r["train_matmul_fraction"] = r["train_flops_per_s"] / matmul[r["backend"]]
    report = {
        "robot": robot_name,
        "batch": BATCH,
        "cpu_count": os.cpu_count(),
        "seconds_per_figure": seconds,
        "seconds_total": round(time.perf_counter() - started, 1),
        "rows": rows,
    }
    if as_json:
        click.echo(json.dumps(report, indent=2))
        return
    StdoutConsole().print(_table(report))


def _table(report: dict[str, Any]) -> Table:
    rows = report["rows"]
    modes = [m for m in ("plain", "compiled") if any(f"train_samples_per_s_{m}" in r for r in rows)]
    table = Table(title=f"symbench bench models ({report['robot']}, {report['cpu_count']} CPUs)")
    columns = ["model", "backend"]
    columns += [f"train/s {m}" for m in modes] + ["GFLOP/sample", "of matmul peak"]
    columns += [f"infer us {m}" for m in modes]
    for col in columns:
        table.add_column(col, justify="right")
    for r in rows:
        table.add_row(
            r["model"],
            r["backend"],
            *(
                _figure(r, f"train_samples_per_s_{m}", "{:,.0f}", r["train_best"] == m)
                for m in modes
            ),
            f"{r['train_flops_per_sample'] / 1e9:.2e}",
            f"{r['train_matmul_fraction']:.1%}",
            *(_figure(r, f"infer_batch1_us_{m}", "{:.1f}", r["infer_best"] == m) for m in modes),
        )
    return table


def _figure(row: dict[str, Any], key: str, fmt: str, best: bool) -> str:
    if key not in row:
        return "-"
    text = fmt.format(row[key])
    return f"[bold green]{text}[/]" if best else text

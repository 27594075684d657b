"""`symbench bench models`: training throughput (batch 64), how close it comes to the CPU's
matmul limit, inference latency (batch 1, and the closed loop's lockstep batch of every
reference at every PD fraction on `small`) and the throughput of an evaluator's call (4096
rows), per thread setting.

Every model in both backends, on synthetic data shaped like the robot's, in each backend's
default mode, or (`--modes both`) uncompiled and compiled side by side (torch.compile; JAX:
one jitted call per step vs one jitted scan per epoch for training, eager vs jit for
inference), so the table shows which wins; torch models' latency also as ONNX Runtime runs
their export (`symbench export`: what a controller outside Python would call).

The limit is one honest denominator per thread setting: the best dense-matmul rate either
backend reaches with that setting's cores, measured in the same process as the rows (see
`models_worker`). One thread is how a sweep runs each job; all cores is how `symbench run`
trains in JAX (torch trains there on one thread, `SYMBENCH_TORCH_THREADS`, and the second core
trains the closed loop's model). Latency is measured in the setting with the fewest threads
only: a batch-1 call's matrices are far too small to split among threads, so a second figure
would cost a timing window per row and mode and say nothing new.
"""

from __future__ import annotations

import json
import os
import time
from typing import Any

import click
from rich.console import Group
from rich.table import Table

from symbench.core.bench.model_rates import BATCH, LOCKSTEP
from symbench.core.bench.models_worker import measure_in_child
from symbench.core.bench.threads import ThreadCounts
from symbench.core.common.cli_types import POSITIVE
from symbench.core.common.console import StdoutConsole
from symbench.core.plugin import registry
from symbench.core.plugin.entries import BACKENDS

MODES = ("plain", "compiled")


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
    "--threads",
    "thread_counts",
    type=ThreadCounts(),
    default="1,all",
    show_default=True,
    help="Comma-separated thread settings, each measured in a process of its own on that "
    "many cores: a number, or 'all' (every core this process may use).",
)
@click.option(
    "--seconds", default=1.0, show_default=True, type=POSITIVE, help="Timing window per figure."
)
@click.option("--json", "as_json", is_flag=True, help="Print JSON instead of a table.")
def bench_models(
    robot_name: str,
    names: str,
    backends: str,
    modes: str,
    thread_counts: list[int],
    seconds: float,
    as_json: bool,
) -> None:
    """Training samples/s (batch 64), its share of the best matmul rate either backend
    reaches with the same threads, and batch-1 inference latency, per model, backend and
    thread setting. Progress goes to stderr."""
    from symbench.core.robot.specs import load_robot

    load_robot(robot_name)
    models = [n.strip() for n in names.split(",")]
    chosen = [b.strip() for b in backends.split(",")]
    for backend in chosen:
        for name in models:
            registry.model(name, backend)  # an unknown name fails here, before any child
    started = time.perf_counter()
    settings = []
    for count in thread_counts:
        job = {
            "robot": robot_name,
            "models": models,
            "backends": chosen,
            "modes": modes,
            "seconds": seconds,
            "threads": count,
            "latency": count == thread_counts[0],
        }
        label = _count(count, "thread")

        def relay(line: str, label: str = label) -> None:
            click.echo(f"{label}: {line}", err=True)

        settings.append(measure_in_child(job, relay))
    report = {
        "robot": robot_name,
        "batch": BATCH,
        "lockstep_batch": LOCKSTEP,
        "cpu_count": os.cpu_count(),
        "seconds_per_figure": seconds,
        "seconds_total": round(time.perf_counter() - started, 1),
        "settings": settings,
    }
    if as_json:
        click.echo(json.dumps(report, indent=2))
        return
    StdoutConsole().print(Group(*(_table(robot_name, s) for s in settings)))


def _table(robot: str, setting: dict[str, Any]) -> Table:
    """One setting's block: its threads and matmul rates above and below, a row per model
    and backend (each row's share of its own backend's rate is in the JSON)."""
    rows = setting["rows"]
    modes = [m for m in MODES if any(f"train_samples_per_s_{m}" in r for r in rows)]
    latency = setting["latency_measured"]
    used = ", ".join(f"{b} {_count(n, 'thread')}" for b, n in setting["threads_used"].items())
    rates = ", ".join(f"{b} {r / 1e9:,.0f}" for b, r in setting["matmul_flops_per_s"].items())
    table = Table(
        title=f"bench models, {robot}: {_count(setting['threads'], 'core')} ({used})",
        caption=f"matmul GFLOP/s: {rates}; best: {setting['best_matmul_backend']}",
    )
    columns = ["model", "backend", *(f"train/s {m}" for m in modes)]
    columns += ["GFLOP/sample", "of best matmul"]
    inference = [*modes, *(["onnx"] if any("infer_batch1_us_onnx" in r for r in rows) else [])]
    columns += [f"infer us {m}" for m in inference] if latency else []
    columns += [f"lockstep us {m}" for m in inference] if latency else []
    columns += [f"eval rows/s {m}" for m in modes] if latency else []
    for col in columns:
        table.add_column(col, justify="right")
    for r in rows:
        cells = [r["model"], r["backend"]]
        cells += [
            _figure(r, f"train_samples_per_s_{m}", "{:,.0f}", r["train_best"] == m) for m in modes
        ]
        cells += [f"{r['train_flops_per_sample'] / 1e9:.2e}", f"{r['share_of_best_matmul']:.1%}"]
        if latency:
            cells += [
                _figure(r, f"infer_{size}_us_{m}", "{:.1f}", r[best] == m)
                for size, best in (("batch1", "infer_best"), ("lockstep", "lockstep_best"))
                for m in inference
            ]
            cells += [_figure(r, f"predict_rows_per_s_{m}", "{:,.0f}", False) for m in modes]
        table.add_row(*cells)
    return table


def _count(n: int, noun: str) -> str:
    return f"{n} {noun}{'' if n == 1 else 's'}"


def _figure(row: dict[str, Any], key: str, fmt: str, best: bool) -> str:
    if key not in row:
        return "-"
    text = fmt.format(row[key])
    return f"[bold green]{text}[/]" if best else text

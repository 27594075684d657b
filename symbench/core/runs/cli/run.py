"""`symbench run`: train and evaluate one model on one dataset, print a table, write a record.

`--dataset` names the data (any cached id, generated or imported; default: the standard
dataset of `--robot` and the preset), `--preset` the budgets (default: a standard dataset's
own preset, else `small`); the robot is the dataset's, so `--robot` may be left out with
`--dataset` and must agree with it when given."""

from __future__ import annotations

import time
from typing import Any

import click
from rich.markup import escape
from rich.table import Table

from symbench.core.common.console import StdoutConsole
from symbench.core.data.cli import split_option
from symbench.core.runs.options import run_options, spec_fields
from symbench.core.runs.results import ResultRecord
from symbench.core.runs.run_config import budget_text, check_names, train_config
from symbench.core.runs.runner import run as run_spec
from symbench.core.runs.spec import (
    DEFAULT_EVALUATORS,
    FIRST_RESULT_EVALUATORS,
    RunSpec,
    default_preset,
    resolve_robot,
)
from symbench.core.runs.timing import CPU_KEY, STAGES, evaluator_of


@click.command("run")
@run_options(
    "model",
    "robot",
    "dataset",
    "backend",
    "split",
    "split_by",
    "train_values",
    "test_values",
    "seed",
    "preset",
    "variant",
    "evaluators",
    "full",
    "output",
    "workers",
    "protocol",
    "max_steps",
    "max_epochs",
    "parameters",
    "sizes",
    "overwrite",
)
def run(**options: Any) -> None:
    """Train and evaluate MODEL on a robot's standard dataset (generated when missing) or on
    any cached dataset (--dataset).

    Each stage is announced with the time so far; the simulation and training bars estimate
    what remains."""
    spec = _spec(options)
    check_names(spec)  # every name, before the plan is printed
    console = StdoutConsole()
    started = time.perf_counter()

    def announce(stage: str) -> None:
        console.print(f"[bold]{stage}[/] [dim]({time.perf_counter() - started:.0f} s so far)[/]")

    console.print(
        f"{spec.model} on {spec.dataset_id} ({spec.robot}, preset {spec.preset}): dataset, one "
        f"training ({budget_text(train_config(spec))}), then {', '.join(spec.evaluators)}"
    )
    record = run_spec(spec, on_stage=announce)
    console.print(metrics_table(record))
    console.print(time_line(record.timings_s))
    console.print(f"result record: {spec.record_path}", soft_wrap=True)  # whole, to copy


def _spec(options: dict[str, Any]) -> RunSpec:
    """The run the options ask for: a split by a column, the preset and robot of the
    dataset, the first-result or full evaluators resolved."""
    if options["evaluators"] is not None and options["full"]:
        raise click.UsageError("--full and --evaluators choose the evaluators twice; use one")
    dataset = options["dataset"]
    if options["robot"] is None and dataset is None:
        raise click.UsageError("give --robot (its standard dataset) or --dataset")
    columns = (options[k] for k in ("split", "split_by", "train_values", "test_values"))
    resolved = {
        "split": split_option(*columns) or "iid",
        "preset": default_preset(dataset) if options["preset"] is None else options["preset"],
        "robot": options["robot"] if dataset is None else resolve_robot(options["robot"], dataset),
        "evaluators": (DEFAULT_EVALUATORS if options["full"] else FIRST_RESULT_EVALUATORS)
        if options["evaluators"] is None
        else options["evaluators"],
    }
    return RunSpec(**spec_fields({**options, **resolved}))


def time_line(timings: dict[str, float]) -> str:
    """Where the run's time went: wall seconds per stage, each evaluator's own after the
    evaluation's (longest first), and the CPU seconds of the whole run."""
    own = sorted(
        ((n, s) for k, s in timings.items() if (n := evaluator_of(k))), key=lambda x: -x[1]
    )
    parts = []
    for key in (k for k in STAGES if k in timings):
        parts.append(f"{key.removesuffix('_s')} {timings[key]:.0f} s")
        if key == "evaluation_s" and own:
            parts[-1] += " (" + ", ".join(f"{name} {sec:.0f} s" for name, sec in own) + ")"
    cpu = f"; CPU {timings[CPU_KEY]:.0f} s" if CPU_KEY in timings else ""
    return "time: " + ", ".join(parts) + cpu


def metrics_table(record: ResultRecord) -> Table:
    """The record's scalar metrics, one row each; a skipped evaluator (or split) shows its
    one-line reason."""
    m, t = record.model, record.training
    table = Table(
        title=f"{m.name} ({m.backend}) on {record.dataset.id}, split {record.split}, "
        f"seed {record.seed}, {record.samples.train} training samples",
        caption=f"{m.parameters} parameters; {t.config.protocol} protocol: {t.steps} steps "
        f"({t.epochs} epochs), best at step {t.best_step}; stopped: {t.stop_reason}",
    )
    table.add_column("evaluator")
    table.add_column("metric")
    table.add_column("value", justify="right")
    for evaluator, metrics in record.metrics.items():
        for name, value in metrics.items():
            if name == "skipped" and isinstance(value, str):
                table.add_row(evaluator, "[yellow]skipped[/]", escape(value))
            elif name == "skipped_splits" and isinstance(value, dict):
                for split, why in value.items():
                    table.add_row(evaluator, f"[yellow]skipped split {split}[/]", escape(str(why)))
            elif isinstance(value, bool):
                table.add_row(evaluator, name, str(value))
            elif isinstance(value, (int, float)):
                table.add_row(evaluator, name, f"{value:.4g}")
    return table

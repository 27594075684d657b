"""`symbench tune`: the learning rate x width search of one model on one robot's data."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import click
from rich.table import Table

from symbench.core.common.cli_types import POSITIVE, CommaList
from symbench.core.common.console import StdoutConsole
from symbench.core.runs import tune as tuning
from symbench.core.runs.options import run_options, spec_fields
from symbench.core.runs.run_config import check_names
from symbench.core.runs.spec import RunSpec, default_preset, resolve_robot
from symbench.core.runs.tune import DEFAULT_WIDTH_SCALES


@click.command("tune")
@run_options(
    "model",
    "robot",
    "dataset",
    "backend",
    "split",
    "seed",
    "preset",
    "protocol",
    robot={"help": "Registered robot, e.g. hexa."},
    dataset={"help": "A cached dataset id instead of the standard one."},
    split={
        "default": "iid",
        "show_default": True,
        "help": "The split whose training side is searched.",
    },
    preset={"help": "Budgets (default: a standard dataset's own, else small)."},
    protocol={"help": "Training protocol of every trial."},
)
@click.option(
    "--learning-rates",
    type=CommaList(POSITIVE),
    default=None,
    help="Comma-separated learning rates [default: the model's x 1/3, 1, 3].",
)
@click.option(
    "--width-scales",
    type=CommaList(POSITIVE),
    default=",".join(f"{s:g}" for s in DEFAULT_WIDTH_SCALES),
    show_default=True,
    help="Comma-separated factors on the model's width keywords (its ModelEntry.widths).",
)
@run_options(
    "output",
    "workers",
    output={"default": Path("tuning"), "help": ""},
    workers={"help": "Worker processes simulating the dataset when it is missing."},
)
def tune(learning_rates: list[float] | None, width_scales: list[float], **options: Any) -> None:
    """Search learning rate x width for MODEL on validation data only (never the test
    split); resumes an interrupted search from OUTPUT and writes OUTPUT/<run key>.tune.json."""
    robot, dataset = options["robot"], options["dataset"]
    if robot is None and dataset is None:
        raise click.UsageError("give --robot (its standard dataset) or --dataset")
    resolved = {
        "robot": robot if dataset is None else resolve_robot(robot, dataset),
        "preset": options["preset"] or default_preset(dataset),
    }
    spec = RunSpec(**spec_fields({**options, **resolved}), evaluators=(), progress=False)
    check_names(spec)
    entry = tuning.model_entry(spec)
    rates = learning_rates or list(tuning.default_rates(entry))
    console = StdoutConsole()
    output = spec.output
    summary = tuning.tune(spec, rates, width_scales, output, report=console.print)
    console.print(_table(summary))
    console.print(f"summary: {tuning.summary_path(output, spec)}", soft_wrap=True)


def _table(summary: dict) -> Table:
    table = Table(
        title=f"{summary['model']} on {summary['dataset']}, split {summary['split']}: "
        f"best validation loss per trial ({summary['protocol']} protocol)"
    )
    for column in ("learning rate", "width scale", "sizes", "parameters", "steps", "stopped by"):
        table.add_column(column)
    table.add_column("val loss", justify="right")
    best = summary["best"]
    for t in summary["trials"]:
        mark = " [bold](best)[/]" if t == best else ""
        table.add_row(
            f"{t['learning_rate']:g}",
            f"{t['width_scale']:g}",
            ", ".join(f"{k} {v}" for k, v in t["hyper"].items()) or "-",
            str(t["parameters"]),
            str(t["steps"]),
            t["stopped_by"],
            f"{t['best_val_loss']:.4g}{mark}",
        )
    return table

"""`symbench tune`: the learning rate x width search of one model on one robot's data."""

from __future__ import annotations

from pathlib import Path

import click
from rich.table import Table

from symbench.core.common.cli_types import POSITIVE, SEED, WORKERS, CommaList, WritableFolder
from symbench.core.common.console import StdoutConsole
from symbench.core.runs.options import protocol_option
from symbench.core.runs.runner import RunSpec, check_names, default_preset, resolve_robot
from symbench.core.runs.tune import DEFAULT_WIDTH_SCALES


@click.command("tune")
@click.option("--model", "model_name", required=True, help="Registered model, e.g. sdnn.")
@click.option("--robot", "robot_name", default=None, help="Registered robot, e.g. hexa.")
@click.option("--dataset", default=None, help="A cached dataset id instead of the standard one.")
@click.option("--backend", default="torch", show_default=True, help="torch or jax.")
@click.option(
    "--split", default="iid", show_default=True, help="The split whose training side is searched."
)
@click.option("--seed", type=SEED, default=0, show_default=True)
@click.option(
    "--preset", default=None, help="Budgets (default: a standard dataset's own, else small)."
)
@protocol_option("Training protocol of every trial.")
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
@click.option("--output", type=WritableFolder(), default=Path("tuning"), show_default=True)
@click.option(
    "--workers",
    default=2,
    show_default=True,
    type=WORKERS,
    help="Worker processes simulating the dataset when it is missing.",
)
def tune(
    model_name: str,
    robot_name: str | None,
    dataset: str | None,
    backend: str,
    split: str,
    seed: int,
    preset: str | None,
    protocol: str,
    learning_rates: list[float] | None,
    width_scales: list[float],
    output: Path,
    workers: int,
) -> None:
    """Search learning rate x width for MODEL on validation data only (never the test
    split); resumes an interrupted search from OUTPUT and writes OUTPUT/<run key>.tune.json."""
    from symbench.core.runs import tune as tuning

    if robot_name is None and dataset is None:
        raise click.UsageError("give --robot (its standard dataset) or --dataset")
    if dataset is not None:
        robot_name = resolve_robot(robot_name, dataset)
    assert robot_name is not None
    spec = RunSpec(
        model=model_name,
        robot=robot_name,
        backend=backend,
        split=split,
        seed=seed,
        preset=preset or default_preset(dataset),
        protocol=protocol,
        evaluators=(),
        output=output,
        workers=workers,
        progress=False,
        dataset=dataset,
    )
    check_names(spec)
    entry = tuning.model_entry(spec)
    rates = learning_rates or list(tuning.default_rates(entry))
    console = StdoutConsole()
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

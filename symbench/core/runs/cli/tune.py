"""`symbench tune`: the learning rate x width search of one model on one robot's data, and
`symbench tune summarize`: the searches' summaries as the board's table and the lines of
`tuned_rates.toml`."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import click
from click.core import ParameterSource
from rich.table import Table

from symbench.core.common.cli_types import POSITIVE, CommaList, WritableFile
from symbench.core.common.console import StdoutConsole
from symbench.core.runs import tune as tuning
from symbench.core.runs import tune_summary
from symbench.core.runs.options import run_options, spec_fields
from symbench.core.runs.run_config import check_names
from symbench.core.runs.spec import RunSpec, default_preset, resolve_robot
from symbench.core.runs.tune import DEFAULT_WIDTH_SCALES


@click.group("tune", invoke_without_command=True)
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
    model={"required": False},  # not with `summarize`
)
@click.option(
    "--learning-rates",
    type=CommaList(POSITIVE),
    default=None,
    help="Comma-separated learning rates [default: the rate a run on the robot trains with "
    "(its tuned one, else the model's) x 1/3, 1, 3].",
)
@click.option(
    "--width-scales",
    type=CommaList(POSITIVE),
    default=",".join(f"{s:g}" for s in DEFAULT_WIDTH_SCALES),
    show_default=True,
    help="Comma-separated factors on the model's width keywords (its ModelEntry.widths).",
)
@click.option(
    "--extend-edges/--no-extend-edges",
    default=True,
    show_default=True,
    help=f"When the best rate is the grid's smallest or largest, try the next rate past it "
    f"(at the best width), until the best is interior (at most {tuning.MAX_EXTENSIONS} rates).",
)
@run_options(
    "output",
    "workers",
    output={"default": Path("tuning"), "help": ""},
    workers={"help": "Worker processes simulating the dataset when it is missing."},
)
@click.pass_context
def tune(
    ctx: click.Context,
    learning_rates: list[float] | None,
    width_scales: list[float],
    extend_edges: bool,
    **options: Any,
) -> None:
    """Search learning rate x width for MODEL on validation data only (never the test
    split); resumes an interrupted search from OUTPUT and writes OUTPUT/<run key>.tune.json.
    `symbench tune summarize DIR`: the summaries in DIR as a table."""
    if ctx.invoked_subcommand is not None:  # the search's options would be ignored: refused
        given = [p.opts[0] for p in ctx.command.params if _given(ctx, p.name)]
        if given:
            raise click.UsageError(
                f"`symbench tune {ctx.invoked_subcommand}` takes no search options ({given[0]})"
            )
        return
    robot, dataset = options["robot"], options["dataset"]
    if options["model"] is None:
        raise click.UsageError("Missing option '--model'.")
    if robot is None and dataset is None:
        raise click.UsageError("give --robot (its standard dataset) or --dataset")
    resolved = {
        "robot": robot if dataset is None else resolve_robot(robot, dataset),
        "preset": options["preset"] or default_preset(dataset),
    }
    spec = RunSpec(**spec_fields({**options, **resolved}), evaluators=(), progress=False)
    check_names(spec)
    rates = learning_rates or list(tuning.default_rates(spec))
    console = StdoutConsole()
    output = spec.output
    summary = tuning.tune(spec, rates, width_scales, output, console.print, extend_edges)
    console.print(_table(summary))
    if summary["extended_rates"]:
        added = ", ".join(f"{r:g}" for r in summary["extended_rates"])
        console.print(f"rates added past the grid's edge: {added}")
    if summary["best_on_edge"]:
        console.print("the best rate is on the edge of the rates tried: widen the search")
    console.print(f"summary: {tuning.summary_path(output, spec)}", soft_wrap=True)


@tune.command("summarize")
@click.argument("folder", type=click.Path(exists=True, file_okay=False, path_type=Path))
@click.option(
    "--out",
    type=WritableFile(),
    default=None,
    help="Also write the Markdown table to this file (e.g. leaderboards/tuning/summary.md).",
)
def summarize(folder: Path, out: Path | None) -> None:
    """Print every FOLDER/*.tune.json as a Markdown table (robot x model: the chosen rate and
    width, the validation loss per rate, whether the best is on the edge, the dataset and
    commit) and the lines to paste into symbench/plugins/tuned_rates.toml."""
    tune_summary.summarize(folder, out, click.echo)


def _given(ctx: click.Context, name: str | None) -> bool:
    """Whether the option `name` was given (on the command line or by the environment)."""
    source = ctx.get_parameter_source(name) if name else None
    return source not in (None, ParameterSource.DEFAULT)


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

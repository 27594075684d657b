"""`symbench sweep`: many runs, resumable, locally or on a Ray cluster.

The data axis of the grid is either `--robots` (each robot's standard dataset of the preset)
or `--datasets` (cached ids, generated or imported); `--preset` gives the budgets, by default
a standard dataset's own preset, else `small` (as in `symbench run`)."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import click

from symbench.core.common.cli_types import SEED, WORKERS, CommaList, WritableFolder
from symbench.core.runs.options import budget_options, protocol_option, size_option, sizes_from
from symbench.core.runs.runner import DEFAULT_EVALUATORS, RunSpec, default_preset


@click.command("sweep")
@click.option(
    "--models", required=True, type=CommaList(), help="Comma-separated, e.g. sdnn,sdgnn,ffnn."
)
@click.option(
    "--robots",
    default=None,
    type=CommaList(),
    help="Comma-separated, e.g. magneto,hexa,nona: their standard datasets of the preset.",
)
@click.option(
    "--datasets",
    "--dataset",
    "datasets",
    default=None,
    type=CommaList(),
    help="Comma-separated cached dataset ids, generated or imported (instead of --robots).",
)
@click.option(
    "--splits",
    default=None,
    type=CommaList(),
    help="Comma-separated splits (default: iid, or only the --split-by split).",
)
@click.option(
    "--split-by",
    default=None,
    help="Add a split by a scenario column: heading, yaw, inclination, direction or seed "
    "(with --train and --test).",
)
@click.option(
    "--train", "train_values", default=None, type=CommaList(), help="--split-by's training values."
)
@click.option(
    "--test", "test_values", default=None, type=CommaList(), help="--split-by's test values."
)
@click.option(
    "--seeds",
    default="0,1,2",
    show_default=True,
    type=CommaList(SEED),
    help="Comma-separated seeds.",
)
@click.option(
    "--backends", default="torch", show_default=True, type=CommaList(), help="torch, jax or both."
)
@click.option(
    "--preset",
    default=None,
    help="The budgets of every run; default: a standard dataset's own preset, else small.",
)
@click.option(
    "--variant",
    type=click.Choice(["acc", "next"]),
    default=None,
    help="Input variant of every run (default: each model's; closed-loop control uses next: "
    "with a noisy preset, the closed-loop evaluator then judges the run's own model).",
)
@protocol_option("Training protocol of every run (see `symbench run`).")
@budget_options("every run")
@click.option(
    "--parameters",
    type=click.IntRange(min=1),
    default=None,
    help="Scale every model's widths to the parameter count nearest this (matched size).",
)
@size_option(
    "A build keyword of every model, e.g. ring=1 (see `symbench run`); repeatable. Give such "
    "runs their own --output."
)
@click.option(
    "--evaluators", default=",".join(DEFAULT_EVALUATORS), show_default=True, type=CommaList()
)
@click.option("--output", type=WritableFolder(), default=Path("results"), show_default=True)
@click.option(
    "--workers",
    default=1,
    show_default=True,
    type=WORKERS,
    help="Worker processes at once: local runs in parallel (and the simulations of "
    "a missing dataset).",
)
@click.option("--executor", type=click.Choice(["local", "ray"]), default="local", show_default=True)
@click.option(
    "--address",
    default=None,
    help="Ray cluster address HOST:PORT (default: start a local cluster).",
)
@click.option(
    "--overwrite",
    is_flag=True,
    help="Run again and replace records of another configuration found at the runs' paths "
    "(refused otherwise).",
)
def sweep(
    models: list[str],
    robots: list[str] | None,
    datasets: list[str] | None,
    splits: list[str] | None,
    split_by: str | None,
    train_values: list[str] | None,
    test_values: list[str] | None,
    seeds: list[int],
    backends: list[str],
    preset: str | None,
    variant: str | None,
    protocol: str,
    max_steps: int | None,
    max_epochs: int | None,
    parameters: int | None,
    sizes: tuple[str, ...],
    evaluators: list[str],
    output: Path,
    workers: int,
    executor: str,
    address: str | None,
    overwrite: bool,
) -> None:
    """Run every combination; runs with a record of their configuration are skipped, so it
    resumes."""
    from symbench.core.data.cli import split_option
    from symbench.core.runs import sweep as sweeping

    column = split_option(None, split_by, train_values, test_values)
    if column is None:
        splits = splits or ["iid"]
    else:
        splits = [*(splits or []), column]
    if (robots is None) == (datasets is None):
        raise click.UsageError("give --robots (their standard datasets) or --datasets, not both")
    base = RunSpec(
        model="",
        robot="",
        preset=preset or "small",
        variant=variant,
        protocol=protocol,
        max_steps=max_steps,
        max_epochs=max_epochs,
        parameters=parameters,
        sizes=tuple(sizes_from(sizes).items()),
        evaluators=tuple(evaluators),
        output=output,
        workers=workers,
        progress=False,
        overwrite=overwrite,
    )
    if robots is not None:
        specs = sweeping.plan(models, robots, splits, seeds, backends, base)
    else:
        specs = [
            spec
            for did in datasets or ()
            for spec in sweeping.plan(
                models,
                (),
                splits,
                seeds,
                backends,
                replace(base, preset=preset or default_preset(did)),
                datasets=[did],
            )
        ]
    sweeping.sweep(specs, workers=workers, executor=executor, address=address, report=click.echo)

"""`symbench sweep`: many runs, resumable, locally or on a Ray cluster.

The data axis of the grid is either `--robots` (each robot's standard dataset of the preset)
or `--datasets` (cached ids, generated or imported); `--preset` gives the budgets, by default
a standard dataset's own preset, else `small` (as in `symbench run`)."""

from __future__ import annotations

from dataclasses import replace
from typing import Any

import click

from symbench.core.common.cli_types import SEED, CommaList
from symbench.core.data.cli import split_option
from symbench.core.runs import sweep as sweeping
from symbench.core.runs.options import run_options, spec_fields
from symbench.core.runs.spec import DEFAULT_EVALUATORS, RunSpec, default_preset

EVERY = "every run"


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
@run_options(
    "split_by",
    "train_values",
    "test_values",
    split_by={
        "help": "Add a split by a scenario column: heading, yaw, inclination, direction "
        "or seed (with --train and --test)."
    },
    train_values={"help": "--split-by's training values."},
    test_values={"help": "--split-by's test values."},
)
@click.option(
    "--seeds",
    default="0,1,2,3,4",
    show_default=True,
    type=CommaList(SEED),
    help="Comma-separated seeds.",
)
@click.option(
    "--backends", default="torch", show_default=True, type=CommaList(), help="torch, jax or both."
)
@run_options(
    "preset",
    "variant",
    "protocol",
    "max_steps",
    "max_epochs",
    "parameters",
    "sizes",
    "evaluators",
    "output",
    "workers",
    subject=EVERY,
    variant={
        "help": "Input variant of every run (default: each model's; closed-loop control "
        "uses next: with a noisy preset, the closed-loop evaluator then judges the run's "
        "own model)."
    },
    sizes={
        "help": "A build keyword of every model, e.g. ring=1 (see `symbench run`); "
        "repeatable. Give such runs their own --output."
    },
    evaluators={"default": ",".join(DEFAULT_EVALUATORS), "show_default": True, "help": ""},
    workers={
        "default": 1,
        "help": "Worker processes at once: local runs in parallel (and the "
        "simulations of a missing dataset).",
    },
)
@click.option("--executor", type=click.Choice(["local", "ray"]), default="local", show_default=True)
@click.option(
    "--address",
    default=None,
    help="Ray cluster address HOST:PORT (default: start a local cluster).",
)
@run_options("overwrite")
def sweep(
    models: list[str],
    robots: list[str] | None,
    datasets: list[str] | None,
    splits: list[str] | None,
    seeds: list[int],
    backends: list[str],
    executor: str,
    address: str | None,
    **options: Any,
) -> None:
    """Run every combination; runs with a record of their configuration are skipped, so it
    resumes."""
    column = split_option(
        None, *(options.pop(k) for k in ("split_by", "train_values", "test_values"))
    )
    if column is None:
        splits = splits or ["iid"]
    else:
        splits = [*(splits or []), column]
    if (robots is None) == (datasets is None):
        raise click.UsageError("give --robots (their standard datasets) or --datasets, not both")
    preset = options["preset"]
    base = RunSpec(
        **spec_fields({**options, "preset": preset or "small"}),
        model="",
        robot="",
        progress=False,
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
    sweeping.sweep(
        specs, workers=base.workers, executor=executor, address=address, report=click.echo
    )

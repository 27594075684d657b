"""`symbench run`: train and evaluate one model on one dataset, print a table, write a record.

`--dataset` names the data (any cached id, generated or imported; default: the standard
dataset of `--robot` and the preset), `--preset` the budgets (default: a standard dataset's
own preset, else `small`); the robot is the dataset's, so `--robot` may be left out with
`--dataset` and must agree with it when given."""

from __future__ import annotations

import time
from pathlib import Path

import click
from rich.markup import escape
from rich.table import Table

from symbench.core.common.cli_types import EPOCHS, SEED, WORKERS, CommaList, WritableFolder
from symbench.core.common.console import StdoutConsole
from symbench.core.config.presets import PRESETS
from symbench.core.data.cli import split_option
from symbench.core.runs.options import budget_options, protocol_option, size_option, sizes_from
from symbench.core.runs.results import ResultRecord
from symbench.core.runs.runner import (
    DEFAULT_EVALUATORS,
    FIRST_RESULT_EVALUATORS,
    RunSpec,
    budget_text,
    check_names,
    default_preset,
    resolve_robot,
    train_config,
)
from symbench.core.runs.runner import run as run_spec


@click.command("run")
@click.option("--model", "model_name", required=True, help="Registered model, e.g. sdnn.")
@click.option(
    "--robot",
    "robot_name",
    default=None,
    help="Registered robot, e.g. hexa: trains on its standard dataset of the preset "
    "(with --dataset: the dataset's robot, may be left out).",
)
@click.option(
    "--dataset",
    "dataset",
    default=None,
    help="A cached dataset id, generated or imported (see `symbench list datasets`); "
    "default: the robot's standard dataset of the preset.",
)
@click.option("--backend", default="torch", show_default=True, help="torch or jax.")
@click.option("--split", default=None, help="A registered split (default: iid).")
@click.option(
    "--split-by",
    default=None,
    help="Split by a scenario column instead: heading, yaw, inclination, direction or seed "
    "(with --train and --test).",
)
@click.option(
    "--train",
    "train_values",
    default=None,
    type=CommaList(),
    help="With --split-by: the column's values to train on, e.g. 0,90.",
)
@click.option(
    "--test",
    "test_values",
    default=None,
    type=CommaList(),
    help="With --split-by: the column's values to test on, e.g. 180,270 (others are unused).",
)
@click.option("--seed", default=0, show_default=True, type=SEED)
@click.option(
    "--preset",
    default=None,
    help=f"{', '.join(PRESETS)}: epoch cap, evaluation budgets, horizons (see `symbench "
    "presets`); default: a standard dataset's own preset, else small.",
)
@click.option(
    "--variant",
    type=click.Choice(["acc", "next"]),
    default=None,
    help="Input variant (default: the model's; closed-loop control uses next).",
)
@click.option(
    "--evaluators",
    default=None,
    type=CommaList(),
    help="Comma-separated evaluator names (see `symbench list evaluators`); default: "
    f"{', '.join(FIRST_RESULT_EVALUATORS)}, which need one training.",
)
@click.option(
    "--full",
    is_flag=True,
    help=f"The full evaluation of sweeps and boards: {', '.join(DEFAULT_EVALUATORS)} "
    "(three more trainings and closed-loop rollouts).",
)
@click.option(
    "--output",
    type=WritableFolder(),
    default=Path("results"),
    show_default=True,
    help="Folder for the record, checkpoints and plots.",
)
@click.option(
    "--workers",
    default=2,
    show_default=True,
    type=WORKERS,
    help="Worker processes at once, simulating the dataset when it is missing.",
)
@protocol_option(
    "Training protocol: converge (early stopping on validation loss within a budget of "
    "gradient steps, the same for every model), cosine (the same, the learning rate "
    "decayed to zero at the budget) or paper (the paper's overfitting rule)."
)
@budget_options("the run")
@click.option(
    "--parameters",
    type=EPOCHS,
    default=None,
    help="Scale the model's widths to the parameter count nearest this (compare models at "
    "matched size).",
)
@size_option(
    "A build keyword of the model, e.g. ring=1 (sdnn: each leg also sees its neighbours); "
    "repeatable, applied after --parameters. The record keeps it; the run's key does not name "
    "it, so give such runs their own --output."
)
@click.option(
    "--overwrite",
    is_flag=True,
    help="Replace a record of another configuration at the record's path (refused otherwise).",
)
def run(
    model_name: str,
    robot_name: str | None,
    dataset: str | None,
    backend: str,
    split: str | None,
    split_by: str | None,
    train_values: list[str] | None,
    test_values: list[str] | None,
    seed: int,
    preset: str | None,
    variant: str | None,
    evaluators: list[str] | None,
    full: bool,
    output: Path,
    workers: int,
    protocol: str,
    max_steps: int | None,
    max_epochs: int | None,
    parameters: int | None,
    sizes: tuple[str, ...],
    overwrite: bool,
) -> None:
    """Train and evaluate MODEL on a robot's standard dataset (generated when missing) or on
    any cached dataset (--dataset).

    Each stage is announced with the time so far; the simulation and training bars estimate
    what remains."""
    if evaluators is not None and full:
        raise click.UsageError("--full and --evaluators choose the evaluators twice; use one")
    if robot_name is None and dataset is None:
        raise click.UsageError("give --robot (its standard dataset) or --dataset")
    split = split_option(split, split_by, train_values, test_values) or "iid"
    if preset is None:
        preset = default_preset(dataset)
    if dataset is not None:
        robot_name = resolve_robot(robot_name, dataset)
    assert robot_name is not None
    if evaluators is None:
        evaluators = list(DEFAULT_EVALUATORS if full else FIRST_RESULT_EVALUATORS)
    console = StdoutConsole()
    spec = RunSpec(
        model=model_name,
        robot=robot_name,
        backend=backend,
        split=split,
        seed=seed,
        preset=preset,
        variant=variant,
        evaluators=tuple(evaluators),
        output=output,
        workers=workers,
        protocol=protocol,
        max_steps=max_steps,
        max_epochs=max_epochs,
        parameters=parameters,
        sizes=tuple(sizes_from(sizes).items()),
        dataset=dataset,
        overwrite=overwrite,
    )
    check_names(spec)  # every name, before the plan is printed
    started = time.perf_counter()

    def announce(stage: str) -> None:
        console.print(f"[bold]{stage}[/] [dim]({time.perf_counter() - started:.0f} s so far)[/]")

    console.print(
        f"{model_name} on {spec.dataset_id} ({robot_name}, preset {preset}): dataset, one "
        f"training ({budget_text(train_config(spec))}), then {', '.join(evaluators)}"
    )
    record = run_spec(spec, on_stage=announce)
    console.print(metrics_table(record))
    console.print(f"result record: {spec.record_path}", soft_wrap=True)  # whole, to copy


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

"""`symbench check-equivariance`: the kit on a registered model and robot, from the shell."""

from __future__ import annotations

import json

import click
from rich.table import Table

from symbench.core.common.cli_types import SEED
from symbench.core.common.console import StdoutConsole
from symbench.core.plugin import registry
from symbench.core.plugin.entries import BACKENDS
from symbench.testing.equivariance import EquivarianceReport, check_model
from symbench.testing.groups import robot_group


@click.command("check-equivariance")
@click.option("--model", "model_name", required=True, help="Registered model name, e.g. sdnn.")
@click.option("--robot", "robot_name", required=True, help="Registered robot, e.g. hexa.")
@click.option(
    "--backend",
    type=click.Choice([*BACKENDS, "all"]),
    default="all",
    show_default=True,
    help="Backend to check; 'all' checks every backend the model has.",
)
@click.option(
    "--samples",
    default=32,
    show_default=True,
    type=click.IntRange(min=1),
    help="Random inputs per group element.",
)
@click.option(
    "--seed", default=0, show_default=True, type=SEED, help="Seed of parameters and inputs."
)
@click.option("--json", "as_json", is_flag=True, help="Print JSON instead of tables.")
@click.pass_context
def check_equivariance(
    ctx: click.Context,
    model_name: str,
    robot_name: str,
    backend: str,
    samples: int,
    seed: int,
    as_json: bool,
) -> None:
    """Max relative error of f(g.x) vs g.f(x) per group element, float64 and float32.

    Exits non-zero when a model that claims equivariance breaks it; a model that claims
    none is reported as not equivariant, which is not a failure.
    """
    group = robot_group(robot_name)
    if backend == "all":
        entries = [e for e in registry.collect("models").values() if e.name == model_name]
        entries = entries or [registry.model(model_name)]  # raises, naming the closest models
    else:
        entries = [registry.model(model_name, backend)]
    reports = [check_model(e, group, n_samples=samples, seed=seed) for e in entries]
    if as_json:
        click.echo(json.dumps([r.to_dict() for r in reports], indent=2))
    else:
        for r in reports:
            _print(r)
    if not all(r.passed for r in reports):
        ctx.exit(1)


def _print(report: EquivarianceReport) -> None:
    console = StdoutConsole()
    colour = "green" if report.equivariant else ("red" if report.claims else "yellow")
    title = (
        f"{report.model}/{report.backend} on {report.group} ({report.n_legs} legs): "
        f"[{colour}]{report.verdict}[/]"
    )
    if not report.measured:
        console.print(f"{title}\n  {report.note}")
        return
    table = Table(title=title, title_justify="left")
    for col in (
        "element",
        "leg i -> leg",
        *(f"{d} (tol {t:g})" for d, t in report.tolerances.items()),
    ):
        table.add_column(col)
    for e in report.elements:
        cells = [
            f"{e.errors[d]:.2e}" if e.errors[d] <= t else f"[red]{e.errors[d]:.2e}[/]"
            for d, t in report.tolerances.items()
        ]
        table.add_row(e.element, str(e.perm), *cells)
    console.print(table)

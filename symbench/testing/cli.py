"""`symbench check-equivariance`: the kit on a registered model and robot, from the shell."""

from __future__ import annotations

import json

import click
from rich.markup import escape
from rich.table import Table

from symbench.core.common.cli_types import SEED
from symbench.core.common.console import StdoutConsole
from symbench.core.data.views.model_dims import dims_for
from symbench.core.plugin import registry
from symbench.core.plugin.entries import BACKENDS
from symbench.core.robot.specs import load_robot
from symbench.core.runs.options import size_option, sizes_from
from symbench.core.symmetry.groups import LegGroup
from symbench.core.training.buildable import check_buildable
from symbench.testing.equivariance import EquivarianceReport, check_model
from symbench.testing.groups import robot_geometry_group
from symbench.testing.model_group import measure_symmetry_group
from symbench.testing.raw_states import robot_frames


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
@click.option(
    "--group",
    "which_group",
    type=click.Choice(["declared", "geometry"]),
    default="declared",
    show_default=True,
    help="The robot's declared group, or its geometry group: the declared rotations with the "
    "mirrors its geometry has (what `symbench sim check` verifies in simulation).",
)
@size_option(
    "A build keyword of the model, e.g. mirror=1 (sdnn, sdgnn: equivariant to mirrors too); "
    "repeatable."
)
@click.option(
    "--group-of-model",
    is_flag=True,
    help="Also measure the model's own symmetry group (the leg permutations it is "
    "equivariant to) against the robot's.",
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
    which_group: str,
    sizes: tuple[str, ...],
    group_of_model: bool,
    as_json: bool,
) -> None:
    """Max relative error of f(g.x) vs g.f(x) per group element, float64 and float32, with
    g acting on raw states (base turned, legs relabelled) and the model's view recomputed.

    Known-wrong transformations run as controls and must fail. Exits non-zero when a model
    that claims equivariance breaks it; a model that claims none gets its measured error,
    which is not a failure.
    """
    if backend == "all":
        entries = [e for e in registry.collect("models").values() if e.name == model_name]
        entries = entries or [registry.model(model_name)]  # raises, naming the closest models
    else:
        entries = [registry.model(model_name, backend)]
    hyper = sizes_from(sizes)
    n_legs = load_robot(robot_name).n_legs
    for entry in entries:  # a size that cannot build the network, refused before any check
        check_buildable(entry, dims_for(entry.view, entry.variant, n_legs), hyper, hyper)
    group: LegGroup | str = robot_name
    frames = None
    if which_group == "geometry":
        group, frames = robot_geometry_group(robot_name), robot_frames(robot_name)
    reports = [
        check_model(e, group, n_samples=samples, seed=seed, hyper=hyper, frames=frames)
        for e in entries
    ]
    groups = [measure_symmetry_group(e, robot_name, seed=seed) for e in entries]
    groups = groups if group_of_model else []
    if as_json:
        dicts = [r.to_dict() for r in reports]
        for d, g in zip(dicts, groups, strict=False):
            d["symmetry_group"] = g.to_dict()
        click.echo(json.dumps(dicts, indent=2))
    else:
        for r in reports:
            _print(r)
        for g in groups:
            StdoutConsole().print(
                f"{g.model}/{g.backend} symmetry group ({len(g.tested)} permutations tested, "
                f"{g.view} view relabelled): {g.verdict}"
            )
    if not all(r.passed for r in reports):
        ctx.exit(1)


def _print(report: EquivarianceReport) -> None:
    console = StdoutConsole()
    colour = "green" if report.equivariant else ("red" if report.claims else "yellow")
    title = (
        f"{report.model}/{report.backend} on {report.group} ({report.n_legs} legs): "
        f"[{colour}]{escape(report.verdict)}[/]"
    )
    console.print(title, soft_wrap=True)  # the verdict whole on one line, however narrow
    if not report.measured:
        console.print(f"  {report.note}")
        return
    table = Table()
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
    controls = Table(
        title="controls (known-wrong transformations: must fail)", title_justify="left"
    )
    for col in ("control", "as element", *report.tolerances, "result"):
        controls.add_column(col)
    for c in report.controls:
        result = "fails, as it must" if c.failed(report.tolerances) else "[red]PASSES[/]"
        controls.add_row(
            c.control, c.element, *(f"{c.errors[d]:.2e}" for d in report.tolerances), result
        )
    if report.controls:
        console.print(controls)

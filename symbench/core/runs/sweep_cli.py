"""`symbench sweep`: many runs, resumable, locally or on a Ray cluster."""

from __future__ import annotations

from pathlib import Path

import click

from symbench.core.common.cli_types import SEED, WORKERS, CommaList, WritableFolder
from symbench.core.runs.runner import DEFAULT_EVALUATORS, RunSpec


@click.command("sweep")
@click.option(
    "--models", required=True, type=CommaList(), help="Comma-separated, e.g. sdnn,sdgnn,ffnn."
)
@click.option(
    "--robots", required=True, type=CommaList(), help="Comma-separated, e.g. magneto,hexa,nona."
)
@click.option(
    "--splits", default="iid", show_default=True, type=CommaList(), help="Comma-separated splits."
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
@click.option("--preset", default="small", show_default=True)
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
def sweep(
    models: list[str],
    robots: list[str],
    splits: list[str],
    seeds: list[int],
    backends: list[str],
    preset: str,
    evaluators: list[str],
    output: Path,
    workers: int,
    executor: str,
    address: str | None,
) -> None:
    """Run every combination; runs with a valid record are skipped, so it resumes."""
    from symbench.core.runs import sweep as sweeping

    base = RunSpec(
        model="",
        robot="",
        preset=preset,
        evaluators=tuple(evaluators),
        output=output,
        workers=workers,
        progress=False,
    )
    specs = sweeping.plan(models, robots, splits, seeds, backends, base)
    sweeping.sweep(specs, workers=workers, executor=executor, address=address, report=click.echo)

"""`symbench sweep`: many runs, resumable, locally or on a Ray cluster."""

from __future__ import annotations

from pathlib import Path

import click

from symbench.core.runner import DEFAULT_EVALUATORS, RunSpec


def _names(value: str) -> list[str]:
    return [v.strip() for v in value.split(",") if v.strip()]


@click.command("sweep")
@click.option("--models", required=True, help="Comma-separated, e.g. sdnn,sdgnn,ffnn.")
@click.option("--robots", required=True, help="Comma-separated, e.g. magneto,hexa,nona.")
@click.option("--splits", default="iid", show_default=True, help="Comma-separated splits.")
@click.option("--seeds", default="0,1,2", show_default=True, help="Comma-separated seeds.")
@click.option("--backends", default="torch", show_default=True, help="torch, jax or both.")
@click.option("--preset", default="small", show_default=True)
@click.option("--evaluators", default=",".join(DEFAULT_EVALUATORS), show_default=True)
@click.option("--output", type=click.Path(path_type=Path), default=Path("results"), show_default=True)
@click.option("--workers", default=1, show_default=True, type=int, help="Local processes.")
@click.option("--executor", type=click.Choice(["local", "ray"]), default="local", show_default=True)
@click.option("--address", default=None, help="Ray cluster address (default: start a local one).")
def sweep(models: str, robots: str, splits: str, seeds: str, backends: str, preset: str,
          evaluators: str, output: Path, workers: int, executor: str, address: str | None) -> None:
    """Run every combination; runs with a valid record are skipped, so it resumes."""
    from symbench.core import sweep as sweeping

    base = RunSpec(model="", robot="", preset=preset, evaluators=tuple(_names(evaluators)),
                   output=output, progress=False)
    specs = sweeping.plan(_names(models), _names(robots), _names(splits),
                          [int(s) for s in _names(seeds)], _names(backends), base)
    sweeping.sweep(specs, workers=workers, executor=executor, address=address, report=click.echo)

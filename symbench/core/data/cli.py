"""`symbench data generate|info|import|export`."""

from __future__ import annotations

import json
from pathlib import Path

import click
from rich.console import Console
from rich.table import Table

from symbench.core.common.cli_types import SEED, WORKERS, WritableFolder
from symbench.core.data.presets import PRESETS

console = Console()


@click.group("data")
def data() -> None:
    """Generate, inspect, import and export datasets (cached under $SYMBENCH_HOME)."""


def _print_failures(failures: list[dict], shown: int = 10) -> None:
    for failure in failures[:shown]:
        console.print(f"  [yellow]failed[/] #{failure['id']}: {failure['failure']}")
    if len(failures) > shown:
        console.print(
            f"  ... and {len(failures) - shown} more (`symbench data info ID --json` lists all)"
        )


@data.command("generate")
@click.option("--robot", required=True, help="Registered robot, e.g. hexa.")
@click.option(
    "--preset",
    "preset_name",
    default="small",
    show_default=True,
    type=click.Choice(list(PRESETS)),
    help="Whose scenario grid (see `symbench presets`).",
)
@click.option(
    "--workers",
    default=2,
    show_default=True,
    type=WORKERS,
    help="Worker processes at once, each simulating one trajectory.",
)
@click.option("--progress/--no-progress", default=True, show_default=True)
def generate_command(robot: str, preset_name: str, workers: int, progress: bool) -> None:
    """Simulate a preset's scenario grid; resumes an interrupted run."""
    from symbench.core.data.generation import generate

    report = generate(robot, preset_name, workers, show_progress=progress)
    kept = report.n_trajectories + report.n_failed - report.n_simulated
    console.print(f"dataset [bold]{report.dataset_id}[/] at {report.root}")
    console.print(
        f"  {report.n_trajectories} trajectories, {report.n_samples} samples; "
        f"{report.n_failed} failed (robot detached, left out); "
        f"{report.n_simulated} simulated in {report.seconds:.1f} s, {kept} kept"
    )
    _print_failures(report.failures)
    console.print(f"  content hash {report.content_hash}")
    _print_reference(report.dataset_id, report.content_hash)


def _print_reference(dataset_id: str, content_hash: str) -> None:
    """Whether this machine made the same bytes as the reference committed with symbench."""
    from symbench.core.data.metadata import library_versions
    from symbench.core.data.reference_hashes import reference_hash

    expected = reference_hash(dataset_id, library_versions())
    if expected is None:
        console.print("  no reference hash for this id and these library versions")
    elif expected == content_hash:
        console.print("  matches the reference hash committed with symbench")
    else:
        console.print(
            f"  [yellow]warning:[/] the reference hash committed with symbench is "
            f"{expected}: this machine generated different data",
            soft_wrap=True,
        )


@data.command("info")
@click.argument("dataset_id")
@click.option("--seed", default=0, show_default=True, type=SEED, help="Seed of the splits.")
@click.option("--json", "as_json", is_flag=True, help="Print JSON.")
def info_command(dataset_id: str, seed: int, as_json: bool) -> None:
    """Trajectories, samples, failures and per-split counts of a cached dataset."""
    from symbench.core.data.dataset import load_dataset
    from symbench.core.data.info import dataset_info

    info = dataset_info(load_dataset(dataset_id), seed)
    if as_json:
        click.echo(json.dumps(info, indent=2))
        return
    console.print(
        f"[bold]{info['id']}[/] ({info['source']}, robot {info['robot']}): "
        f"{info['trajectories']} trajectories, {info['samples']} samples, "
        f"{info['failed']} failed, {info['size_bytes'] / 1e6:.2f} MB"
    )
    console.print(f"content hash {info['content_hash']}")
    _print_failures(info["failures"])
    table = Table(title=f"splits (seed {seed}): trajectories / samples")
    for column in ("split", "train", "val", "test", "disjoint"):
        table.add_column(column)
    for name, counts in info["splits"].items():
        if "error" in counts:
            table.add_row(name, f"[red]{counts['error']}[/]", "", "", "")
            continue
        cells = [
            f"{counts[p]['trajectories']} / {counts[p]['samples']}"
            for p in ("train", "val", "test")
        ]
        table.add_row(name, *cells, "yes" if counts["disjoint"] else "[red]NO[/]")
    console.print(table)


@data.command("import")
@click.argument("folder", type=click.Path(exists=True, file_okay=False, path_type=Path))
@click.option("--id", "dataset_id", default=None, help="Dataset id (default: the folder's name).")
@click.option("--force", is_flag=True, help="Replace a cached dataset of the same id.")
def import_command(folder: Path, dataset_id: str | None, force: bool) -> None:
    """Import external logs: FOLDER holds import.json and one Parquet/npz file per trajectory."""
    from symbench.core.data.importer import import_logs

    ds = import_logs(folder, dataset_id or folder.resolve().name, force)
    console.print(
        f"imported {len(ds.trajectory_ids)} trajectories ({int(ds.n_samples.sum())} "
        f"samples) as [bold]{ds.id}[/]; content hash {ds.content_hash}"
    )


@data.command("export")
@click.argument("dataset_id")
@click.argument("folder", type=WritableFolder())
@click.option(
    "--format", "fmt", default="parquet", show_default=True, type=click.Choice(["parquet", "npz"])
)
def export_command(dataset_id: str, folder: Path, fmt: str) -> None:
    """Write a cached dataset in the import format (for other tools, or to re-import)."""
    from symbench.core.data.dataset import load_dataset
    from symbench.core.data.importer import export_dataset

    export_dataset(load_dataset(dataset_id), folder, fmt)
    console.print(f"exported {dataset_id} to {folder}")

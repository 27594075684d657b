"""`symbench data generate|info|import|export|symmetry`."""

from __future__ import annotations

import json
from pathlib import Path

import click
from rich.table import Table

from symbench.core.common.cli_types import SEED, WORKERS, CommaList, WritableFolder
from symbench.core.common.console import StdoutConsole
from symbench.core.config.presets import LEGACY_PRESETS, PRESETS
from symbench.core.data.twins import DEFAULT_TWINS

console = StdoutConsole()


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
    type=click.Choice([*PRESETS, *LEGACY_PRESETS]),
    help="Whose climbs (see `symbench presets`); `small@v6` and the like regenerate an "
    "earlier dataset version.",
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
    from symbench.core.data.generation.generate import generate

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
    from symbench.core.data.generation.reference_hashes import no_reference, reference_hash
    from symbench.core.data.storage.metadata import library_versions

    versions = library_versions()
    expected = reference_hash(dataset_id, versions)
    if expected is None:
        console.print(f"  {no_reference(dataset_id, versions)}", soft_wrap=True, markup=False)
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
@click.option(
    "--split-by",
    default=None,
    help="Also show a split by a scenario column (heading, yaw, inclination, direction, "
    "seed), with --train and --test, as `symbench run` takes it.",
)
@click.option("--train", "train_values", default=None, type=CommaList())
@click.option("--test", "test_values", default=None, type=CommaList())
@click.option(
    "--overlap/--no-overlap",
    default=True,
    show_default=True,
    help="Measure each split's image overlap: held-out climbs that are images of training "
    "climbs per symmetry class (seconds per split on a small dataset).",
)
@click.option("--json", "as_json", is_flag=True, help="Print JSON.")
def info_command(
    dataset_id: str,
    seed: int,
    split_by: str | None,
    train_values: list[str] | None,
    test_values: list[str] | None,
    overlap: bool,
    as_json: bool,
) -> None:
    """Trajectories, samples, failures, provenance, per-split counts and scenario values, and
    each split's image overlap, of a cached dataset."""
    from symbench.core.data.dataset import load_dataset
    from symbench.core.data.info import dataset_info

    column = split_option(None, split_by, train_values, test_values)
    info = dataset_info(load_dataset(dataset_id), seed, [column] if column else [], overlap)
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
    for key, value in sorted(info["provenance"].items()):
        console.print(f"{key}: {value}", soft_wrap=True, markup=False)
    for name in info["unknown_columns"]:
        console.print(f"[yellow]unknown:[/] {name} (declared unknown at import; views refuse)")
    for step in (info["import"] or {}).get("steps", []):
        console.print(f"import: {step}", soft_wrap=True, markup=False)
    if info["scenarios"]:
        console.print(f"scenarios: {_values(info['scenarios'])}", markup=False)
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
    sides = Table(title="scenario values on each side of each split")
    for column in ("split", "train", "val", "test"):
        sides.add_column(column)
    for name, counts in info["splits"].items():
        if "error" not in counts:
            sides.add_row(
                name, *(_values(counts[p]["scenarios"]) for p in ("train", "val", "test"))
            )
    console.print(sides)
    if overlap:
        _print_overlap(info["splits"])


def _print_overlap(splits: dict[str, dict]) -> None:
    """Per split and side, each class's exact / near image shares and distinct motions."""
    from rich.markup import escape

    from symbench.core.data.symmetry.compare import CLASSES, EXACT_TOLERANCE, NEAR_TOLERANCE

    table = Table(
        title="image overlap: share of held-out climbs that are images of a training climb, "
        "exact/near (distinct motions on the side, exact~near)",
        caption=f"exact: relative RMS error below {EXACT_TOLERANCE:g}, near: below "
        f"{NEAR_TOLERANCE:g}; classes: none (world frame), heading (scene turned about "
        "gravity), group (legs relabelled, base turned, and heading), mirror (with mirrors)",
    )
    for column in ("split", "side", *CLASSES):
        left = column in ("split", "side")
        table.add_column(column, justify="left" if left else "right", no_wrap=not left)
    for name, counts in splits.items():
        found = counts.get("image_overlap")
        if found is None:
            continue
        if "error" in found:
            table.add_row(name, "", f"[red]{escape(found['error'])}[/]", *[""] * (len(CLASSES) - 1))
            continue
        for side, part in found["sides"].items():
            cells = []
            for cls in CLASSES:
                row = part["classes"][cls]
                motions = str(row["distinct_motions_exact"])
                if row["distinct_motions_near"] != row["distinct_motions_exact"]:
                    motions += f"~{row['distinct_motions_near']}"
                if "exact_image_share" in row:
                    exact, near = row["exact_image_share"], row["near_image_share"]
                    cells.append(f"{exact * 100:.0f}/{near * 100:.0f}% ({motions})")
                else:
                    cells.append(f"({motions})")
            table.add_row(name if side == "train" else "", f"{side} ({part['climbs']})", *cells)
    console.print(table)


def _values(scenarios: dict[str, list]) -> str:
    """`heading 0,90; yaw 0` from {"heading_deg": [0, 90], "yaw_deg": [0]}."""

    def shown(v: object) -> str:
        return f"{v:g}" if isinstance(v, float) else str(v)

    return "; ".join(
        f"{column.removesuffix('_deg')} {','.join(shown(v) for v in values)}"
        for column, values in scenarios.items()
    )


def split_option(
    split: str | None,
    split_by: str | None,
    train: list[str] | None,
    test: list[str] | None,
) -> str | None:
    """The column split that --split-by/--train/--test describe (its name, as records keep
    it, e.g. heading_0_90_vs_180_270), else --split."""
    if split_by is None:
        if train is not None or test is not None:
            raise click.UsageError("--train and --test go with --split-by")
        return split
    if split is not None:
        raise click.UsageError("--split and --split-by choose the split twice; use one")
    if train is None or test is None:
        raise click.UsageError("--split-by needs --train and --test values")
    from symbench.core.common.errors import SymbenchError
    from symbench.core.data.splits import column_split

    try:
        return column_split(split_by, train, test).name
    except SymbenchError as exc:
        raise click.UsageError(str(exc)) from None


@data.command("import")
@click.argument("folder", type=click.Path(exists=True, file_okay=False, path_type=Path))
@click.option("--id", "dataset_id", default=None, help="Dataset id (default: the folder's name).")
@click.option("--force", is_flag=True, help="Replace a cached dataset of the same id.")
@click.option(
    "--dry-run",
    is_flag=True,
    help="Check every file and say what would be derived, dropped and resampled, and why; "
    "write nothing.",
)
def import_command(folder: Path, dataset_id: str | None, force: bool, dry_run: bool) -> None:
    """Import external logs: FOLDER holds import.json and one Parquet/npz file per trajectory."""
    from symbench.core.data.importing.importer import import_logs, prepare_import

    dataset_id = dataset_id or folder.resolve().name
    prepared = prepare_import(folder, dataset_id)
    for line in prepared[0].lines():
        console.print(line, soft_wrap=True, markup=False)
    if dry_run:
        console.print("dry run: nothing written")
        return
    ds = import_logs(folder, dataset_id, force, prepared)
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
    from symbench.core.data.importing.importer import export_dataset

    export_dataset(load_dataset(dataset_id), folder, fmt)
    console.print(f"exported {dataset_id} to {folder}")


@data.command("symmetry")
@click.argument("dataset_id")
@click.option(
    "--output",
    type=WritableFolder(),
    default=None,
    help="Folder for the plot symmetry-<ID>.png (default: symmetry.png in the dataset's folder).",
)
@click.option(
    "--twins",
    type=click.IntRange(min=1),
    default=None,
    help="Construct image pairs from N climbs of a generated dataset, even when it holds "
    "some: each simulated again under every rotation of the group (cached as dataset "
    f"ID-twinsN). Without it, a generated dataset holding none gets {DEFAULT_TWINS}.",
)
@click.option("--json", "as_json", is_flag=True, help="Print JSON (every pair and column).")
def symmetry_command(
    dataset_id: str, output: Path | None, twins: int | None, as_json: bool
) -> None:
    """How symmetric a dataset is: trajectories that are images of each other under the
    robot's group, compared after relabelling, against a noise floor (pairs constructed on
    purpose, saying so, when a generated dataset holds none)."""
    from rich.markup import escape

    from symbench.core.data.dataset import load_dataset
    from symbench.core.data.storage.metadata import dataset_dir
    from symbench.core.data.symmetry.pairing import READING_NAMES
    from symbench.core.data.symmetry.plot import PLOT_NAME, symmetry_png
    from symbench.core.data.twins import symmetry_report

    dataset = load_dataset(dataset_id)
    report = symmetry_report(dataset, twins, show_progress=not as_json)
    name = report.dataset  # the derived dataset of constructed pairs, if any
    plot = output / f"symmetry-{name}.png" if output else dataset_dir(name) / PLOT_NAME
    report.plot = str(symmetry_png(report, plot))
    if as_json:
        click.echo(json.dumps(report.to_dict(), indent=2))
        return
    if report.constructed is not None:
        console.print(report.constructed.sentence(), soft_wrap=True, markup=False)
    elements = sorted({p.element.name for p in report.pairs})
    console.print(
        f"[bold]{escape(name)}[/] (robot {report.robot}, group {report.group}): "
        f"{len(report.pairs)} image pairs among {report.trajectories} trajectories "
        f"({', '.join(elements)}); noise floor from {report.floor_source}"
        + (f" ({report.repeats} repeat pairs)" if report.floor_source == "repeats" else "")
        + f"; scenarios read as {READING_NAMES[report.reading]}"
    )
    shifted = [p for p in report.pairs if p.alignment.aligned and p.alignment.shift]
    if shifted:
        console.print(
            f"{len(shifted)} image pairs start at different phases, aligned on their first "
            f"lift-off (shifts of {', '.join(sorted({str(p.alignment.shift) for p in shifted}))}"
            " rows)"
        )
    if report.unaligned:
        console.print(
            f"{len(report.unaligned)} image pairs could not be aligned: "
            + "; ".join(sorted({escape(p.alignment.how) for p in report.unaligned}))
        )
    if report.floor_note:
        console.print(f"[yellow]noise floor uninformative[/]: {escape(report.floor_note)}")
    table = Table(
        title="relative RMS error after relabelling, against the noise floor",
        caption="; ".join(f"{k}: {', '.join(v['columns'])}" for k, v in report.groups.items()),
    )
    for column in ("group", "error", "floor", "error / floor", "verdict"):
        table.add_column(column, justify="left" if column in ("group", "verdict") else "right")
    for label, row in report.groups.items():
        table.add_row(
            label,
            f"{row['relative_error']:.3g}",
            f"{row['relative_floor']:.3g}",
            "-" if row["ratio"] is None else f"{row['ratio']:.3g}",
            escape(row["verdict"]),
        )
    for flag, share in report.flags.items():
        table.add_row(f"{flag} flags", f"{share:.3g}", "", "", "share of rows differing")
    console.print(table)
    console.print(f"plot: {report.plot}", soft_wrap=True)

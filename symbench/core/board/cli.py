"""`symbench leaderboard`: tables and plots from result records."""

from __future__ import annotations

from pathlib import Path

import click

from symbench.core.common.cli_types import SEED, WritableFolder
from symbench.core.common.errors import SymbenchError


@click.command("leaderboard")
@click.option(
    "--results",
    type=click.Path(path_type=Path, exists=True, file_okay=False),
    default=Path("results"),
    show_default=True,
    help="Folder holding the result records (*.json).",
)
@click.option(
    "--out",
    type=WritableFolder(),
    default=None,
    show_default="leaderboards",
    help="Where the Markdown, CSV and PNG files go (with --html: only when given).",
)
@click.option(
    "--html",
    type=click.Path(path_type=Path, file_okay=False),
    default=None,
    help="Build the static HTML site into this folder instead of the Markdown (both when "
    "--out is given too); a folder a previous build made is replaced whole.",
)
@click.option(
    "--board",
    type=click.Path(path_type=Path, file_okay=False),
    default=Path("leaderboards"),
    show_default=True,
    help="The published board; the site's entry pages say whether it holds each record.",
)
@click.option(
    "--clips",
    is_flag=True,
    help="With --html: on each robot's page, a clip of the closed-loop climb of its best and "
    "worst model beside the expert's, rendered from the runs' checkpoints under --results "
    "(rendering: MUJOCO_GL=osmesa unless set, docs/leaderboard-site.md).",
)
@click.option(
    "--clips-from",
    type=click.Path(path_type=Path, exists=True, file_okay=False),
    default=None,
    help="The results folder holding the runs' checkpoints, when it is not --results "
    "(implies --clips).",
)
@click.option(
    "--without-clips",
    "without_clips",
    multiple=True,
    metavar="DATASET",
    help="With --clips: build this dataset's board page without clips, saying so on the page "
    "(its judged networks are not at hand, e.g. trained on a CPU of another kernel class). "
    "Repeatable.",
)
@click.option(
    "--include-board",
    "include",
    multiple=True,
    type=click.Path(path_type=Path, exists=True, file_okay=False),
    help="Rank the records of this board (its records/ folder, or a folder of records) "
    "beside those of --results; a run under --results is shown as it is there. Repeatable.",
)
def leaderboard(
    results: Path,
    out: Path | None,
    html: Path | None,
    board: Path,
    clips: bool,
    clips_from: Path | None,
    without_clips: tuple[str, ...],
    include: tuple[Path, ...],
) -> None:
    """Aggregate records (mean, std and 95 % bootstrap interval over seeds), rank by test
    RMSE in rank bands, write tables, or with --html a static site (docs/leaderboard-site.md)."""
    from symbench.core.board.included import is_one_of, with_boards
    from symbench.core.board.leaderboard import write_tables
    from symbench.core.board.site import build_site
    from symbench.core.common.paths import writable_folder

    checkpoints = clips_from if clips_from is not None else results if clips else None
    if checkpoints is not None and html is None:
        raise click.UsageError("--clips and --clips-from need --html")
    if without_clips and checkpoints is None:
        raise click.UsageError("--without-clips needs --clips or --clips-from")
    if checkpoints is not None and include:
        raise click.UsageError("--clips renders your own runs' checkpoints: no --include-board")
    markdown = None if html is not None and out is None else out or Path("leaderboards")
    if markdown is not None and is_one_of(markdown, include):
        raise click.UsageError(
            f"--out {markdown} is an included board: its tables would show your records as "
            "its own; give --out a folder of yours"
        )
    records = with_boards(results, include, click.echo)
    if checkpoints is not None:
        from symbench.core.sim.tracking.render import use_software_gl

        use_software_gl()  # before anything loads MuJoCo
    if html is not None:
        site = build_site(results, html, board, checkpoints, records, frozenset(without_clips))
        click.echo(f"wrote {html / 'index.html'} and {len(site) - 1} more files of the site")
    if markdown is not None:
        for path in write_tables(records, writable_folder(markdown, "--out")):
            click.echo(f"wrote {path}")


@click.command("publish")
@click.argument("records", nargs=-1, required=True, type=click.Path(path_type=Path, exists=True))
@click.option(
    "--to",
    "board",
    type=click.Path(path_type=Path),
    default=Path("leaderboards"),
    show_default=True,
    help="The leaderboards folder to merge into.",
)
@click.option(
    "--verify",
    "verify",
    default=0,
    show_default=True,
    type=click.IntRange(min=0),
    help="Re-run this many of RECORDS (a seeded random sample) before accepting them.",
)
@click.option(
    "--verify-seed",
    default=0,
    show_default=True,
    type=SEED,
    help="Seed of the sample that --verify re-runs.",
)
@click.option(
    "--dry-run",
    is_flag=True,
    help="Check RECORDS only and say of each whether publish would accept it; write nothing.",
)
def publish(
    records: tuple[Path, ...], board: Path, verify: int, verify_seed: int, dry_run: bool
) -> None:
    """Check RECORDS (sealed, committed, small/paper preset, registered names, standard
    dataset hash, enough seeds) and merge them; nothing is written when one is refused."""
    from symbench.core.board.publish import dry_run as check_only
    from symbench.core.board.publish import publish as merge

    if dry_run and verify:
        raise click.UsageError("--dry-run checks the records without re-running: no --verify")
    if dry_run:
        refused = check_only(list(records), board, report=click.echo)
        if refused:
            raise SymbenchError(f"publish would refuse these records ({refused} refusals above)")
        click.echo(f"publish would accept these {len(records)} records (nothing was written)")
        return
    for path in merge(
        list(records), board, verify=verify, verify_seed=verify_seed, report=click.echo
    ):
        click.echo(f"wrote {path}")

"""`symbench leaderboard`: tables and plots from result records."""

from __future__ import annotations

from pathlib import Path

import click

from symbench.core.common.cli_types import SEED, WritableFolder


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
    default=Path("leaderboards"),
    show_default=True,
    help="Where the Markdown, CSV and PNG files go.",
)
def leaderboard(results: Path, out: Path) -> None:
    """Aggregate records (mean ± std over seeds), rank by test RMSE, write tables."""
    from symbench.core.board.leaderboard import write_leaderboard

    for path in write_leaderboard(results, out):
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
def publish(records: tuple[Path, ...], board: Path, verify: int, verify_seed: int) -> None:
    """Check RECORDS (sealed, committed, small/paper preset, registered names, standard
    dataset hash, enough seeds) and merge them; nothing is written when one is refused."""
    from symbench.core.board.publish import publish as merge

    for path in merge(
        list(records), board, verify=verify, verify_seed=verify_seed, report=click.echo
    ):
        click.echo(f"wrote {path}")

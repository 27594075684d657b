"""`symbench leaderboard`: tables and plots from result records."""

from __future__ import annotations

from pathlib import Path

import click


@click.command("leaderboard")
@click.option("--results", type=click.Path(path_type=Path), default=Path("results"),
              show_default=True, help="Folder holding the result records (*.json).")
@click.option("--out", type=click.Path(path_type=Path), default=Path("leaderboards"),
              show_default=True, help="Where the Markdown, CSV and PNG files go.")
def leaderboard(results: Path, out: Path) -> None:
    """Aggregate records (mean ± std over seeds), rank by test RMSE, write tables."""
    from symbench.core.leaderboard import write_leaderboard

    for path in write_leaderboard(results, out):
        click.echo(f"wrote {path}")


@click.command("publish")
@click.argument("records", nargs=-1, required=True, type=click.Path(path_type=Path, exists=True))
@click.option("--to", "board", type=click.Path(path_type=Path), default=Path("leaderboards"),
              show_default=True, help="The leaderboards folder to merge into.")
def publish(records: tuple[Path, ...], board: Path) -> None:
    """Validate RECORDS (schema, standard dataset hash, enough seeds) and merge them."""
    from symbench.core.publish import publish as merge

    for path in merge(list(records), board):
        click.echo(f"wrote {path}")

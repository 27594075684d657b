"""The `symbench` command group.

Core commands live next to the code they drive and are imported only when invoked (so that
`symbench --help` does not import torch or JAX); plugins add commands through the
`symbench_commands` hook. A `SymbenchError` becomes one clear line, never a traceback.
"""

from __future__ import annotations

import json
import sys

import click
from rich.console import Console
from rich.table import Table

from symbench import __version__
from symbench.core.entries import describe
from symbench.core.errors import SymbenchError, UnknownNameError
from symbench.core.lazy_group import LazyGroup
from symbench.core.paths import dataset_ids
from symbench.core.plugins import get_host
from symbench.core.registry import KINDS, collect

# name -> "module:attribute" of a click command, imported when first used.
LAZY_COMMANDS: dict[str, str] = {
    "run": "symbench.core.run_command:run",
    "bench": "symbench.core.bench_cli:bench",
    "sim": "symbench.core.sim.cli:sim",
    "leaderboard": "symbench.core.leaderboard_cli:leaderboard",
    "publish": "symbench.core.leaderboard_cli:publish",
    "sweep": "symbench.core.sweep_cli:sweep",
    "data": "symbench.core.data.cli:data",
    "check-equivariance": "symbench.testing.check_command:check_equivariance",
}

stderr = Console(stderr=True)


class SymbenchGroup(LazyGroup):
    """The top-level group: lazily imported core commands, clear errors for unknown names."""

    def resolve_command(self, ctx: click.Context, args: list[str]):
        name = args[0] if args else ""
        if name and not name.startswith("-") and self.get_command(ctx, name) is None:
            raise click.UsageError(str(UnknownNameError("command", name, self.list_commands(ctx))))
        return super().resolve_command(ctx, args)

    def invoke(self, ctx: click.Context):
        try:
            return super().invoke(ctx)
        except SymbenchError as exc:
            raise click.ClickException(str(exc)) from exc


@click.group(cls=SymbenchGroup, lazy_commands=LAZY_COMMANDS,
             context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(__version__, prog_name="symbench")
def cli() -> None:
    """Benchmark learned dynamics of symmetric legged robots."""


def report_plugin_problems() -> None:
    """Name every plugin that failed, on stderr, without stopping the command."""
    for problem in get_host().problems:
        stderr.print(f"[yellow]warning:[/] {problem}", soft_wrap=True)


LIST_KINDS = (*KINDS, "datasets")


@cli.command("list")
@click.argument("kind")
@click.option("--json", "as_json", is_flag=True, help="Print JSON instead of a table.")
def list_command(kind: str, as_json: bool) -> None:
    """List registered models, robots, evaluators, splits, or cached datasets."""
    if kind not in LIST_KINDS:
        raise UnknownNameError("list kind", kind, LIST_KINDS)
    if kind == "datasets":
        rows = [{"name": d} for d in dataset_ids()]
    else:
        rows = [describe(e) for e in collect(kind).values()]
    report_plugin_problems()
    if as_json:
        click.echo(json.dumps(rows, indent=2))
        return
    table = Table(title=f"symbench {kind}")
    columns = list(rows[0]) if rows else ["name"]
    for c in columns:
        table.add_column(c)
    for row in rows:
        table.add_row(*(str(row.get(c, "")) for c in columns))
    Console().print(table)


@cli.command("plugins")
def plugins_command() -> None:
    """Installed plugins with their distribution, version and hooks (JSON)."""
    host = get_host()
    for kind in KINDS:  # calling every hook surfaces plugins that raise
        collect(kind, host)
    click.echo(json.dumps(host.describe(), indent=2))


def build_cli() -> click.Group:
    """A fresh command group: the core commands plus those that plugins add."""
    group = SymbenchGroup(name=cli.name, commands=dict(cli.commands), callback=cli.callback,
                          params=cli.params, help=cli.help, lazy_commands=LAZY_COMMANDS,
                          context_settings=cli.context_settings)
    get_host().call("symbench_commands", cli=group)
    return group


def main() -> None:
    try:
        build_cli()(prog_name="symbench")
    except SymbenchError as exc:  # raised outside a command, e.g. while adding commands
        stderr.print(f"[red]error:[/] {exc}", soft_wrap=True)
        sys.exit(1)

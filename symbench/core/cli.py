"""The `symbench` command group.

Core commands live next to the code they drive and are imported only when invoked (so that
`symbench --help` does not import torch or JAX); plugins add commands through the
`symbench_commands` hook. Every error is one line on stderr, never a traceback (unless
`--debug`): exit status 2 for a malformed command line (click's usage errors: an unknown
command or option, a value of the wrong type or out of range), 1 for a command that failed
(a `SymbenchError`, or an unexpected exception, reported as an internal error).
"""

from __future__ import annotations

import json
import sys
import warnings

import click
from rich.console import Console
from rich.table import Table
from rich.text import Text

from symbench.core.common.console import StdoutConsole, closed_stdout
from symbench.core.common.errors import SymbenchError, UnknownNameError
from symbench.core.common.jsonfile import one_line
from symbench.core.common.lazy_group import LazyGroup
from symbench.core.common.paths import dataset_ids
from symbench.core.common.version import __version__
from symbench.core.plugin.entries import describe
from symbench.core.plugin.host import duplicate, get_host
from symbench.core.plugin.registry import KINDS, collect, names
from symbench.core.robot.shipped import unshipped

# name -> "module:attribute" of a click command, imported when first used.
LAZY_COMMANDS: dict[str, str] = {
    "run": "symbench.core.runs.cli.run:run",
    "bench": "symbench.core.bench.cli:bench",
    "sim": "symbench.core.sim.cli:sim",
    "leaderboard": "symbench.core.board.cli:leaderboard",
    "publish": "symbench.core.board.cli:publish",
    "sweep": "symbench.core.runs.cli.sweep:sweep",
    "verify": "symbench.core.runs.cli.verify:verify",
    "tune": "symbench.core.runs.cli.tune:tune",
    "data": "symbench.core.data.cli:data",
    "presets": "symbench.core.config.cli:presets",
    "export": "symbench.core.training.cli:export",
    "check-equivariance": "symbench.testing.cli:check_equivariance",
}

stderr = Console(stderr=True)


class SymbenchGroup(LazyGroup):
    """The top-level group: lazily imported core commands, clear errors for unknown names,
    plugin problems reported by every command."""

    def __init__(self, *args, **kwargs) -> None:
        super().__init__(*args, **kwargs)
        self.plugin_commands: dict[str, str] = {}  # command name -> plugin that added it

    def resolve_command(self, ctx: click.Context, args: list[str]):
        name = args[0] if args else ""
        if name and not name.startswith("-") and self.get_command(ctx, name) is None:
            raise click.UsageError(str(UnknownNameError("command", name, self.list_commands(ctx))))
        return super().resolve_command(ctx, args)

    def make_context(self, *args, **kwargs) -> click.Context:
        try:  # parsing prints --help and --version
            return super().make_context(*args, **kwargs)
        except BrokenPipeError:
            closed_stdout()

    def invoke(self, ctx: click.Context):
        reported = report_plugin_problems()  # before a long command starts ...
        try:
            return super().invoke(ctx)
        except (click.ClickException, click.exceptions.Exit, click.Abort):
            raise  # click's own: usage errors (2), exit statuses, Ctrl-C
        except BrokenPipeError:
            closed_stdout()  # the reader went away (`| head`): not an error of the command
        except Exception as exc:
            if ctx.params.get("debug"):
                raise
            if isinstance(exc, SymbenchError):
                raise click.ClickException(str(exc)) from exc
            raise click.ClickException(
                f"internal error: {type(exc).__name__}: {one_line(exc)}"
                " (run with --debug for the traceback)"
            ) from exc
        finally:
            report_plugin_problems(reported)  # ... and what its hooks raised meanwhile

    def add_plugin_commands(self) -> None:
        """Each plugin's `symbench_commands`, added to a scratch group of its own so that a
        name taken by the core or another plugin is an error naming both, never a silent
        replacement (of `publish`, say)."""
        host = get_host()
        scratch: dict[str, click.Group] = {}
        host.call_each(
            "symbench_commands", lambda plugin: {"cli": scratch.setdefault(plugin, click.Group())}
        )
        for plugin, group in scratch.items():
            for name, command in group.commands.items():
                if name in self.plugin_commands:
                    raise duplicate(
                        "command",
                        name,
                        str(host.info[self.plugin_commands[name]]),
                        str(host.info[plugin]),
                    )
                if name in self.commands or name in self.lazy_commands:
                    raise duplicate(
                        "command", name, f"symbench {__version__} (core)", str(host.info[plugin])
                    )
                self.add_command(command, name)
                self.plugin_commands[name] = plugin


@click.group(
    cls=SymbenchGroup,
    lazy_commands=LAZY_COMMANDS,
    context_settings={"help_option_names": ["-h", "--help"]},
)
@click.version_option(__version__, prog_name="symbench")
@click.option("--debug", is_flag=True, help="Show the traceback of any error.")
def cli(debug: bool) -> None:
    """Benchmark learned dynamics of symmetric legged robots."""


def report_plugin_problems(already: int = 0) -> int:
    """Name every plugin that failed since the first `already` problems, one line each on
    stderr, without stopping the command; returns how many have been reported."""
    problems = get_host().problems
    for problem in problems[already:]:
        warn(str(problem))
    return len(problems)


def warn(message: str) -> None:
    """One `warning:` line on stderr: the command goes on."""
    stderr.print(Text.assemble(("warning:", "yellow"), f" {message}"), soft_wrap=True)


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
    if kind == "robots":  # listed, but unusable: say so before anyone generates data
        for problem in filter(None, map(unshipped, (row["name"] for row in rows))):
            warn(problem)
    if as_json:
        click.echo(json.dumps(rows, indent=2))
        return
    console = StdoutConsole()
    console.print(rows_table(f"symbench {kind}", rows, console))


def rows_table(title: str, rows: list[dict], console: Console) -> Table:
    """One row per entry; on a terminal too narrow for that, one block of field/value lines
    per entry (long values wrap, names fold, nothing is cut off)."""
    columns = list(rows[0]) if rows else ["name"]
    rows = [{c: _shown(v) for c, v in r.items()} for r in rows]
    widths = {c: max([len(c), *(len(r.get(c, "")) for r in rows)]) for c in columns}
    table = Table(title=title)
    for i, c in enumerate(columns):  # the first column (names) is never folded (no_wrap: rich
        # would otherwise try to narrow the widest column first and crop the table instead)
        first = i == 0
        table.add_column(c, overflow="fold", min_width=widths[c] if first else None, no_wrap=first)
    for row in rows:
        table.add_row(*(row.get(c, "") for c in columns))
    # the names in full, every other column at least 12 characters (or its longest value)
    needed = widths[columns[0]] + sum(min(12, widths[c]) for c in columns[1:])
    if needed + 3 * len(columns) + 1 <= console.width:
        return table
    blocks = Table(title=title, show_header=False)
    blocks.add_column("field", style="bold", overflow="fold", max_width=max(map(len, columns)))
    blocks.add_column("value", overflow="fold")
    for row in rows:
        for i, c in enumerate(columns):
            blocks.add_row(c, row.get(c, ""), end_section=i == len(columns) - 1)
    return blocks


def _shown(value: object) -> str:
    """A field as a table cell: lists (an entry's tuples) comma-separated, mappings (a model's
    learning rate per robot) as `key value` pairs."""
    if isinstance(value, dict):
        return ", ".join(f"{k} {v}" for k, v in value.items())
    return ", ".join(map(str, value)) if isinstance(value, list) else str(value)


@cli.command("plugins")
@click.pass_context
def plugins_command(ctx: click.Context) -> None:
    """Installed plugins with their hooks, and every name they register, with distribution
    and version (JSON)."""
    host = get_host()
    registered = names(host)  # calls every hook first, so plugins that raise are listed too
    root = ctx.find_root().command
    assert isinstance(root, SymbenchGroup)
    registered += [
        host.registered("command", name, plugin) for name, plugin in root.plugin_commands.items()
    ]
    click.echo(json.dumps({**host.describe(), "names": registered}, indent=2))


def build_cli() -> click.Group:
    """A fresh command group: the core commands plus those that plugins add."""
    group = SymbenchGroup(
        name=cli.name,
        commands=dict(cli.commands),
        callback=cli.callback,
        params=cli.params,
        help=cli.help,
        lazy_commands=LAZY_COMMANDS,
        context_settings=cli.context_settings,
    )
    group.add_plugin_commands()
    return group


def show_warning(message, category, filename, lineno, file=None, line=None) -> None:
    """Warnings on the command line are one line each (`warning: ...`), like plugin problems."""
    warn(str(message))


# The exit status of a command whose standard output was closed by its reader (`| head`):
# 128 + SIGPIPE, what the shell reports for any program that a closed pipe stopped.


def main() -> None:
    warnings.showwarning = show_warning
    try:
        build_cli()(prog_name="symbench")
    except SymbenchError as exc:  # raised outside a command, e.g. while adding commands
        stderr.print(f"[red]error:[/] {exc}", soft_wrap=True)
        sys.exit(1)
    except BrokenPipeError:  # outside a command, e.g. `symbench --help | head -1`
        closed_stdout()

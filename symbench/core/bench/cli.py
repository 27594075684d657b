"""`symbench bench`: performance figures, each subcommand imported only when run."""

from __future__ import annotations

import click

from symbench.core.common.lazy_group import LazyGroup

# subcommand -> "module:attribute" of a click command
BENCH_COMMANDS: dict[str, str] = {
    "sim": "symbench.core.bench.sim:bench_sim",
    "models": "symbench.core.bench.models:bench_models",
}


@click.group("bench", cls=LazyGroup, lazy_commands=BENCH_COMMANDS)
def bench() -> None:
    """Speed figures measured side by side in one run (JSON with --json)."""

"""`symbench bench`: performance figures, each subcommand imported only when run."""

from __future__ import annotations

import importlib

import click

# subcommand -> "module:attribute" of a click command
BENCH_COMMANDS: dict[str, str] = {
    "sim": "symbench.core.sim.bench:bench_sim",
    "models": "symbench.core.bench_models:bench_models",
}


class LazyBenchGroup(click.Group):
    def list_commands(self, ctx: click.Context) -> list[str]:
        return sorted(set(super().list_commands(ctx)) | set(BENCH_COMMANDS))

    def get_command(self, ctx: click.Context, name: str) -> click.Command | None:
        if name in BENCH_COMMANDS and name not in self.commands:
            module, attr = BENCH_COMMANDS[name].split(":")
            self.add_command(getattr(importlib.import_module(module), attr), name)
        return super().get_command(ctx, name)


@click.group("bench", cls=LazyBenchGroup)
def bench() -> None:
    """Speed figures measured side by side in one run (JSON with --json)."""

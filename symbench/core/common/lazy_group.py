"""A click group whose subcommands are imported on first use, so `--help` stays fast."""

from __future__ import annotations

import click

from symbench.core.common.lazy import Lazy


class LazyGroup(click.Group):
    """Subcommands named 'module:attribute' in `lazy_commands` load when first asked for."""

    def __init__(self, *args, lazy_commands: dict[str, str] | None = None, **kwargs) -> None:
        super().__init__(*args, **kwargs)
        self.lazy_commands = dict(lazy_commands or {})

    def list_commands(self, ctx: click.Context) -> list[str]:
        return sorted(set(super().list_commands(ctx)) | set(self.lazy_commands))

    def get_command(self, ctx: click.Context, name: str) -> click.Command | None:
        if name in self.lazy_commands and name not in self.commands:
            self.add_command(Lazy(self.lazy_commands[name]).resolve(), name)
        return super().get_command(ctx, name)

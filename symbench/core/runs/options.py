"""Command-line options that `run`, `sweep` and `tune` share, written once."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import click

from symbench.core.common.cli_types import EPOCHS
from symbench.core.config.protocols import PROTOCOLS


def protocol_option(help_text: str) -> Callable[[Any], Any]:
    """`--protocol converge|cosine|paper` (see symbench.core.training.loop), default converge."""
    return click.option(
        "--protocol",
        type=click.Choice(PROTOCOLS),
        default="converge",
        show_default=True,
        help=help_text,
    )


def budget_options(subject: str) -> Callable[[Any], Any]:
    """`--max-steps` (converge, cosine) and `--max-epochs` (paper): override the preset's
    training budget of `subject` ("the run", "every run")."""

    def decorate(command: Any) -> Any:
        steps = click.option(
            "--max-steps",
            type=EPOCHS,
            default=None,
            help=f"Override the preset's budget of gradient steps of {subject} (converge, cosine).",
        )
        epochs = click.option(
            "--max-epochs",
            type=EPOCHS,
            default=None,
            help=f"Override the preset's epoch cap of {subject} (paper).",
        )
        return steps(epochs(command))

    return decorate


def size_option(help_text: str) -> Callable[[Any], Any]:
    """`--size NAME=INT`, repeatable: build keywords of the model (see `sizes_from`)."""
    return click.option("--size", "sizes", multiple=True, metavar="NAME=INT", help=help_text)


def sizes_from(pairs: tuple[str, ...]) -> dict[str, int]:
    """NAME=INT pairs as build keywords; a malformed one is a usage error naming it."""
    out = {}
    for pair in pairs:
        name, _, value = pair.partition("=")
        if not name.isidentifier() or not value.lstrip("-").isdigit():
            raise click.BadParameter(f"{pair!r} is not NAME=INT", param_hint="'--size'")
        out[name] = int(value)
    return out

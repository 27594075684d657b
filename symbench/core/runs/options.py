"""Command-line options that `run`, `sweep` and `tune` share, written once."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import click

from symbench.core.training.protocols import PROTOCOLS


def protocol_option(help_text: str) -> Callable[[Any], Any]:
    """`--protocol converge|paper` (see symbench.core.training.loop), default converge."""
    return click.option(
        "--protocol",
        type=click.Choice(PROTOCOLS),
        default="converge",
        show_default=True,
        help=help_text,
    )

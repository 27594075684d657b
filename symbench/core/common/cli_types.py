"""What the command line accepts, checked while the command line is parsed: a bad value is a
usage error (exit status 2) naming the option, before any minute of work is spent.

`--workers N` means the same in every command: at most N worker processes at once (N >= 1),
simulating trajectories (`data generate`, and `run`/`verify` when they generate a dataset)
or running runs (`sweep`).
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import click

from symbench.core.common.paths import unwritable_reason
from symbench.core.common.seeds import SEED_MAX

SEED = click.IntRange(0, SEED_MAX)
WORKERS = click.IntRange(min=1)
EPOCHS = click.IntRange(min=1)


class FiniteFloat(click.FloatRange):
    """A float range that also refuses nan and inf (click's own ranges let nan through)."""

    name = "finite float"

    def convert(
        self, value: Any, param: click.Parameter | None, ctx: click.Context | None
    ) -> float:
        number = super().convert(value, param, ctx)
        if not math.isfinite(number):
            self.fail(f"{value!r} is not a finite number", param, ctx)
        return number

    def _describe_range(self) -> str:
        """click writes an unbounded range as 'x<=None'."""
        if self.min is None and self.max is None:
            return "finite"
        return super()._describe_range()


POSITIVE = FiniteFloat(min=0, min_open=True)
NON_NEGATIVE = FiniteFloat(min=0)
INCLINATION = FiniteFloat(0, 180)  # degrees: 0 floor, 90 wall, 180 ceiling


class CommaList(click.ParamType):
    """Comma-separated values, each converted by `item`; empty lists and repeats are refused
    (a repeated seed would run the same run twice, racing for one record)."""

    name = "list"

    def __init__(self, item: click.ParamType = click.STRING) -> None:
        self.item = item

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> list:
        if isinstance(value, list):
            return value
        items = [
            self.item.convert(v.strip(), param, ctx) for v in str(value).split(",") if v.strip()
        ]
        if not items:
            self.fail(f"{value!r} names nothing (a comma-separated list is expected)", param, ctx)
        repeated = sorted({str(v) for v in items if items.count(v) > 1})
        if repeated:
            self.fail(f"{value!r} repeats {', '.join(repeated)}", param, ctx)
        return items


class WritableFolder(click.ParamType):
    """A folder that exists or can be made, and into which files can be written."""

    name = "folder"

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> Path:
        folder = Path(value)
        reason = unwritable_reason(folder)
        if reason is not None:
            self.fail(f"{str(folder)!r}: cannot write there ({reason})", param, ctx)
        return folder


class WritableFile(click.ParamType):
    """A file to write: not a folder, in a folder that exists or can be made and into which
    files can be written (checked before any work, as `WritableFolder`)."""

    name = "file"

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> Path:
        path = Path(value)
        if "\x00" in str(path):
            self.fail(f"{str(path)!r} holds a NUL character", param, ctx)
        if path.is_dir():
            self.fail(f"{str(path)!r} is a folder, not a file", param, ctx)
        reason = unwritable_reason(path.parent)
        if reason is not None:
            self.fail(f"{str(path)!r}: cannot write there ({reason})", param, ctx)
        return path

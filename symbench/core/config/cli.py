"""`symbench presets`: every preset's sizes, budgets and horizons, side by side.

The descriptions (sentences) are printed above the tables, not in a row of them: in a column
a dozen characters wide a sentence wraps into a word per line and its long words break.
"""

from __future__ import annotations

import json
from dataclasses import asdict, fields
from typing import Any

import click
from rich.console import Group, RenderableType
from rich.table import Table

from symbench.core.common.console import StdoutConsole
from symbench.core.config.presets import PRESETS, Preset

# the groups of a Preset, in the order they are shown
SECTIONS = tuple(f.name for f in fields(Preset) if f.name not in ("name", "description"))
LABELS_WIDTH = 38  # the section and setting columns, with their borders
PRESET_WIDTH = 14  # the least a preset's column needs for its values to read as words
NOTE = (
    "dataset: a grid (one trajectory per combination of its axes) or climbs drawn from "
    "continuous distributions (dataset v7); the budgets below it are not part of it"
)


def presets_doc() -> dict[str, dict[str, Any]]:
    """Every preset as JSON-ready data, by name: exactly the Preset objects' fields."""
    return json.loads(json.dumps({name: asdict(p) for name, p in PRESETS.items()}))


def _cell(value: Any) -> str:
    if isinstance(value, list):
        return ", ".join(_cell(v) for v in value) if value else "-"
    if isinstance(value, float):
        return f"{value:g}"
    return str(value)


def presets_descriptions(doc: dict[str, dict[str, Any]]) -> Table:
    """Each preset's name and what it is for, one per line, wrapped at words."""
    grid = Table.grid(padding=(0, 2))
    grid.add_column(style="bold", no_wrap=True)
    grid.add_column()
    for name, p in doc.items():
        grid.add_row(name, p["description"])
    return grid


def presets_tables(doc: dict[str, dict[str, Any]], width: int) -> list[Table]:
    """`presets_table`s of as many presets side by side as `width` columns hold (at least
    one): squeezed into 80 columns, every value would wrap into a column of one word."""
    per_table = max(1, (width - LABELS_WIDTH) // PRESET_WIDTH)
    names = list(doc)
    return [
        presets_table({n: doc[n] for n in names[i : i + per_table]})
        for i in range(0, len(names), per_table)
    ]


def presets_view(doc: dict[str, dict[str, Any]], width: int) -> RenderableType:
    """The whole `symbench presets` page: the descriptions, the note on datasets, the tables."""
    return Group(
        "[bold]symbench presets[/]",
        presets_descriptions(doc),
        "",
        NOTE,
        *presets_tables(doc, width),
    )


def presets_table(doc: dict[str, dict[str, Any]]) -> Table:
    """One column per preset, one row per number, grouped by section (a number a preset
    does not have, such as a grid's axes beside drawn climbs, shows as a blank)."""
    table = Table()
    table.add_column("section", style="bold")
    table.add_column("setting", no_wrap=True)
    for name in doc:
        table.add_column(name, overflow="fold")
    for i, section in enumerate(SECTIONS):
        if i:
            table.add_section()
        values = [p[section] for p in doc.values()]
        if not isinstance(values[0], dict):  # a number of its own (version, failure share)
            table.add_row(section.replace("_", " "), "", *(_cell(v) for v in values))
            continue
        settings = list(dict.fromkeys(s for v in values for s in v))
        for j, setting in enumerate(settings):
            label = section.replace("_", " ") if j == 0 else ""
            table.add_row(label, setting, *(_cell(v.get(setting, "")) for v in values))
    return table


@click.command("presets")
@click.option("--json", "as_json", is_flag=True, help="Print JSON instead of a table.")
def presets(as_json: bool) -> None:
    """Every preset's dataset grid, training budget, evaluation budgets and horizons."""
    doc = presets_doc()
    if as_json:
        click.echo(json.dumps(doc, indent=2))
        return
    console = StdoutConsole()
    console.print(presets_view(doc, console.width))

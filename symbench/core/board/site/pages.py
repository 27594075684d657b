"""What each page of the site shows, computed from the records and their aggregate
(`leaderboard.aggregate`): plain values that the templates only lay out, so that every
number is worked out once, here and in the leaderboard."""

from __future__ import annotations

from collections import defaultdict
from collections.abc import Callable, Iterable
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import pandas as pd

from symbench.core.board.cells import cell_of
from symbench.core.board.leaderboard import COLUMNS, MIN_SEEDS, protocol_of
from symbench.core.board.site import names
from symbench.core.board.site.names import GroupKey
from symbench.core.board.site.provenance import Provenance, provenance
from symbench.core.board.site.seeds import SeedSummary, seed_summary
from symbench.core.board.summary import split_order
from symbench.core.runs.results import RecordV1

CLOSED_LOOP = "closed-loop"  # its columns come last: they measure control, not the fit
OVER_SEEDS = "mean [95 % bootstrap interval] over seeds"


@dataclass(frozen=True)
class Cell:
    text: str
    value: str  # what sorting compares: the mean at full precision, "" when missing


@dataclass(frozen=True)
class Column:
    name: str  # the leaderboard's column name (leaderboard.csv has the same)
    title: str  # what the column holds, shown as the header's tooltip
    numeric: bool
    read: Callable[[pd.Series], Cell] = field(compare=False, repr=False)


@dataclass(frozen=True)
class Row:
    key: GroupKey
    rank: int  # by mean test RMSE: what sorting compares
    band: str  # the rank band shown (`statistics.rank_bands`)
    entry: str  # the group's entry page
    cells: tuple[Cell, ...]  # one per column of the page


@dataclass(frozen=True)
class SplitTable:
    split: str
    anchor: str
    rows: tuple[Row, ...]


@dataclass(frozen=True)
class ProtocolSection:
    protocol: str
    anchor: str
    tables: tuple[SplitTable, ...]


@dataclass(frozen=True)
class BoardPage:
    """One dataset of one robot: a table per protocol and split."""

    robot: str
    dataset: str
    preset: str
    path: str
    columns: tuple[Column, ...]
    sections: tuple[ProtocolSection, ...]
    models: tuple[str, ...]  # the filter's choices


@dataclass(frozen=True)
class EntryPage:
    """One row of a board table: its seeds side by side, then the provenance of each."""

    key: GroupKey
    robot: str
    preset: str
    path: str
    board: str  # the board page, at the row's table
    columns: tuple[Column, ...]
    row: Row
    summary: SeedSummary
    runs: tuple[Provenance, ...]


def mean_ci(name: str) -> Callable[[pd.Series], Cell]:
    """The mean [95 % interval] over seeds of an aggregated column, as on the Markdown
    board."""

    def read(row: pd.Series) -> Cell:
        mean = float(row[f"{name}_mean"])
        return Cell(cell_of(row, name), "" if np.isnan(mean) else repr(mean))

    return read


def _seeds(row: pd.Series) -> Cell:
    flag = "" if row.seeds >= MIN_SEEDS else f" (<{MIN_SEEDS})"
    return Cell(f"{row.seeds}{flag}", str(row.seeds))


def _parameters(row: pd.Series) -> Cell:
    return Cell(str(row.parameters), str(row.parameters))


def _stopped_by(row: pd.Series) -> Cell:
    return Cell(row.stopped_by, row.stopped_by)


def _has(rows: pd.DataFrame, name: str) -> bool:
    return f"{name}_mean" in rows and bool(rows[f"{name}_mean"].notna().any())


def columns(rows: pd.DataFrame) -> tuple[Column, ...]:
    """The columns with data among `rows`: the evaluators' metrics (COLUMNS), how each
    model trained, then the closed loop's metrics."""

    def metrics(closed_loop: bool) -> list[Column]:
        return [
            Column(name, f"{evaluator} · {metric}: {OVER_SEEDS}", True, mean_ci(name))
            for (evaluator, metric), name in COLUMNS.items()
            if (evaluator == CLOSED_LOOP) == closed_loop and _has(rows, name)
        ]

    training = [
        Column("parameters", "trainable parameters", True, _parameters),
        Column("steps", f"gradient steps trained: {OVER_SEEDS}", True, mean_ci("steps")),
        Column("epochs", f"passes over the training data: {OVER_SEEDS}", True, mean_ci("epochs")),
        Column("stopped_by", "why training stopped, with the number of seeds", False, _stopped_by),
        Column("seeds", f"seeds averaged (flagged below {MIN_SEEDS})", True, _seeds),
    ]
    training = [c for c in training if c.name != "steps" or _has(rows, "steps")]
    return tuple(metrics(False) + training + metrics(True))


def group_of(record: RecordV1) -> GroupKey:
    m = record.model
    return GroupKey(
        record.dataset.id, protocol_of(record), record.split, m.name, m.variant, m.backend
    )


def row_key(row: pd.Series) -> GroupKey:
    """The group of an aggregate row."""
    return GroupKey(row.dataset, row.protocol, row.split, row.model, row.variant, row.backend)


def _row(row: pd.Series, page_columns: tuple[Column, ...]) -> Row:
    key = row_key(row)
    cells = tuple(c.read(row) for c in page_columns)
    return Row(key, int(row["rank"]), row.rank_band, names.entry_page(key), cells)


def _by_split(rows: pd.DataFrame) -> list[tuple[str, pd.DataFrame]]:
    """The splits as the headline page orders them: iid, the unseen ones, the fractions."""
    return sorted(rows.groupby("split", sort=True), key=lambda item: split_order(str(item[0])))


def board_pages(table: pd.DataFrame) -> list[BoardPage]:
    """A page per (robot, dataset) of the aggregate, rows in rank order."""
    pages = []
    for (robot, did, preset), rows in table.groupby(["robot", "dataset", "preset"], sort=True):
        page_columns = columns(rows)
        sections = tuple(
            ProtocolSection(
                protocol,
                names.anchor(protocol),
                tuple(
                    SplitTable(
                        split,
                        names.anchor(protocol, split),
                        tuple(_row(r, page_columns) for _, r in part.iterrows()),
                    )
                    for split, part in _by_split(by_protocol)
                ),
            )
            for protocol, by_protocol in rows.groupby("protocol", sort=True)
        )
        models = tuple(sorted(rows.model.unique()))
        pages.append(
            BoardPage(
                robot, did, preset, names.board_page(robot, did), page_columns, sections, models
            )
        )
    return pages


def entry_pages(
    boards: Iterable[BoardPage], records: Iterable[tuple[Path, RecordV1]], board: Path
) -> list[EntryPage]:
    """A page per row of the board pages: its numbers, then each seed's record and whether
    the published `board` holds it."""
    runs: dict[GroupKey, list[tuple[Path, RecordV1]]] = defaultdict(list)
    for path, record in records:
        runs[group_of(record)].append((path, record))
    pages = []
    for page in boards:
        for section in page.sections:
            for split_table in section.tables:
                for row in split_table.rows:
                    seeds = sorted(runs[row.key], key=lambda run: run[1].seed)
                    shown = [(r, provenance(p, r, board)) for p, r in seeds]
                    pages.append(
                        EntryPage(
                            key=row.key,
                            robot=page.robot,
                            preset=page.preset,
                            path=row.entry,
                            board=f"{page.path}#{split_table.anchor}",
                            columns=page.columns,
                            row=row,
                            summary=seed_summary(shown),
                            runs=tuple(run for _, run in shown),
                        )
                    )
    return pages

"""What each page of the site shows, computed from the records and their aggregate
(`leaderboard.aggregate`): plain values that the templates only lay out, so that every
number is worked out once, here and in the leaderboard."""

from __future__ import annotations

from collections import defaultdict
from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path

import pandas as pd

from symbench.core.board.leaderboard import protocol_of
from symbench.core.board.site import names
from symbench.core.board.site.columns import HEADLINE, Cell, Column, board_columns
from symbench.core.board.site.names import GroupKey
from symbench.core.board.site.provenance import Provenance, provenance
from symbench.core.board.site.seeds import SeedSummary, seed_summary
from symbench.core.board.sizes import DEFAULT, by_size, miss_caption, size_of, titled
from symbench.core.board.summary import split_order
from symbench.core.runs.results import RecordV1


@dataclass(frozen=True)
class Row:
    key: GroupKey
    rank: int  # by mean test RMSE: what sorting compares
    band: str  # the rank band shown (`statistics.rank_bands`)
    entry: str  # the group's entry page
    cells: tuple[Cell, ...]  # one per column of the page

    @property
    def model(self) -> str:
        return self.key.model

    @property
    def label(self) -> str:
        return self.key.model

    @property
    def link(self) -> str:
        return self.entry

    @property
    def id(self) -> str:
        """The row's id in a compare link: its entry page's name."""
        return names.entry_id(self.key)


@dataclass(frozen=True)
class SplitTable:
    split: str
    anchor: str
    rows: tuple[Row, ...]
    hidden: tuple[str, ...] = ()  # the page's columns folded into the caption
    folded: str = ""  # what they hold, e.g. 'variant acc, backend torch'


@dataclass(frozen=True)
class ProtocolSection:
    """One protocol at one size (`board.sizes`): its tables are ranked apart from others."""

    protocol: str
    anchor: str
    tables: tuple[SplitTable, ...]
    size: str = DEFAULT
    note: str = ""  # a matched size's target, tolerance and each model's miss

    @property
    def title(self) -> str:
        return titled(f"{self.protocol} protocol", self.size)


@dataclass(frozen=True)
class BoardPage:
    """One dataset of one robot: a table per protocol, size and split."""

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


def group_of(record: RecordV1) -> GroupKey:
    m = record.model
    return GroupKey(
        record.dataset.id,
        protocol_of(record),
        record.split,
        m.name,
        m.variant,
        m.backend,
        size_of(record),
    )


def row_key(row: pd.Series) -> GroupKey:
    """The group of an aggregate row."""
    return GroupKey(
        row.dataset, row.protocol, row.split, row.model, row.variant, row.backend, row["size"]
    )


def _row(row: pd.Series, page_columns: tuple[Column, ...]) -> Row:
    key = row_key(row)
    cells = tuple(c.read(row) for c in page_columns)
    return Row(key, int(row["rank"]), row.rank_band, names.entry_page(key), cells)


def _by_split(rows: pd.DataFrame) -> list[tuple[str, pd.DataFrame]]:
    """The splits as the headline page orders them: iid, the unseen ones, the fractions."""
    return sorted(rows.groupby("split", sort=True), key=lambda item: split_order(str(item[0])))


def fold(columns: tuple[Column, ...], rows: tuple[Row, ...]) -> tuple[tuple[str, ...], str]:
    """The columns that hold one value over all of a table's rows (two or more), but the
    rank and the headline metrics, with what they hold: the caption says it once
    ('variant acc, backend torch') instead of every row; one without data there is left out."""
    if len(rows) < 2:
        return (), ""
    hidden, said = [], []
    for i, column in enumerate(columns):
        shown = {row.cells[i].shown for row in rows}
        if column.name in ("rank", *HEADLINE) or len(shown) > 1:
            continue
        hidden.append(column.name)
        value = shown.pop()
        said += [] if value == "-" else [f"{column.name} {value}"]  # no data here: left out
    return tuple(hidden), ", ".join(said)


def _split_table(
    split: str, anchor: str, rows: pd.DataFrame, columns: tuple[Column, ...]
) -> SplitTable:
    shown = tuple(_row(r, columns) for _, r in rows.iterrows())
    return SplitTable(split, anchor, shown, *fold(columns, shown))


def _section(
    protocol: str, size: str, rows: pd.DataFrame, columns: tuple[Column, ...]
) -> ProtocolSection:
    """A protocol's tables at one size; a default size's anchors stay as they were."""
    where = (protocol,) if size == DEFAULT else (protocol, size)
    tables = tuple(
        _split_table(split, names.anchor(*where, split), part, columns)
        for split, part in _by_split(rows)
    )
    return ProtocolSection(protocol, names.anchor(*where), tables, size, miss_caption(rows, size))


def board_pages(table: pd.DataFrame) -> list[BoardPage]:
    """A page per (robot, dataset) of the aggregate, rows in rank order."""
    pages = []
    for (robot, did, preset), rows in table.groupby(["robot", "dataset", "preset"], sort=True):
        page_columns = board_columns(rows)
        sections = tuple(
            _section(str(protocol), size, part, page_columns)
            for protocol, by_protocol in rows.groupby("protocol", sort=True)
            for size, part in by_size(by_protocol)
        )
        models = tuple(sorted(rows.model.unique()))
        pages.append(
            BoardPage(
                robot,
                did,
                preset,
                names.board_page(robot, did),
                page_columns,
                sections,
                models,
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

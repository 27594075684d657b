"""The index page's overview: per robot, dataset and protocol a model x split table of the
headline metrics (test torque RMSE with its interval, the best rank band marked; the
closed-loop score where records have it), whether each model is equivariant, and the
findings in plain words (`findings`). Every number is the aggregate's
(`leaderboard.aggregate`), written as the board tables write it."""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, replace
from pathlib import Path

import pandas as pd

from symbench.core.board.site import names
from symbench.core.board.site.columns import BEST, RMSE, SCORES, Cell, Column, has, mean_ci
from symbench.core.board.site.findings import findings
from symbench.core.board.site.pages import group_of, row_key
from symbench.core.board.sizes import DEFAULT, by_size, titled
from symbench.core.board.summary import model_labels, split_order
from symbench.core.runs.results import RecordV1

EQUIVARIANT = (
    "Whether the model is built equivariant under the robot's symmetry group, as its "
    "plugin declares (ModelEntry.equivariant, checked by symbench's kit) and its records state."
)


@dataclass(frozen=True)
class OverviewRow:
    """A model (with its variant and backend) across the splits of one table."""

    model: str
    label: str
    cells: tuple[Cell, ...]
    link: None = None  # the board tables' rows link to an entry page; its cells do here
    id: str = ""  # no compare box: a row spans several entries


@dataclass(frozen=True)
class OverviewTable:
    protocol: str  # with its size (`board.sizes`): a table never mixes either
    anchor: str
    caption: str
    columns: tuple[Column, ...]
    rows: tuple[OverviewRow, ...]
    findings: tuple[str, ...]


@dataclass(frozen=True)
class DatasetOverview:
    robot: str
    dataset: str
    preset: str
    board: str  # its board page
    tables: tuple[OverviewTable, ...]  # one per protocol and size, default sizes first


def equivariance(records: Iterable[tuple[Path, RecordV1]]) -> dict[names.GroupKey, bool]:
    """Each row group's equivariance, as its records state it."""
    return {group_of(record): record.model.equivariant for _, record in records}


def overviews(table: pd.DataFrame, records: list[tuple[Path, RecordV1]]) -> list[DatasetOverview]:
    """The overview of every (robot, dataset) of the aggregate `table`."""
    claims = equivariance(records)
    table = table.assign(equivariant=[claims[row_key(row)] for _, row in table.iterrows()])
    return [
        DatasetOverview(
            str(robot),
            str(did),
            str(preset),
            names.board_page(str(robot), str(did)),
            tuple(
                _table(str(robot), str(did), str(protocol), size, part)
                for protocol, by_protocol in rows.groupby("protocol", sort=True)
                for size, part in by_size(by_protocol)
            ),
        )
        for (robot, did, preset), rows in table.groupby(["robot", "dataset", "preset"], sort=True)
    ]


def _table(robot: str, dataset: str, protocol: str, size: str, rows: pd.DataFrame) -> OverviewTable:
    rows = rows.assign(label=model_labels(rows))
    splits = sorted(rows.split.unique(), key=split_order)
    score = next((s for s in SCORES if has(rows, s)), None)
    scored = [] if score is None else [s for s in splits if has(rows[rows.split == s], score)]
    columns = (
        Column("equivariant", EQUIVARIANT, False, _equivariant),
        *(_split_column(RMSE, split, "lower") for split in splits),
        *(_split_column(score, split, "higher") for split in scored if score is not None),
    )
    groups = rows.groupby(["model", "variant", "backend"], sort=False)  # in rank order
    shown = tuple(
        OverviewRow(str(part.model.iloc[0]), str(part.label.iloc[0]), _cells(columns, part))
        for _, part in groups
    )
    caption = titled(f"{robot}, {dataset}, {protocol} protocol", size) + (
        ": test torque RMSE in N m per split (lower is better), mean [95 % bootstrap "
        f"interval] over seeds, {BEST} the best rank band"
    )
    if score is not None:
        caption += f"; then the closed-loop score {score} (higher is better)"
    return OverviewTable(
        protocol,
        names.anchor("overview", robot, dataset, protocol, *([] if size == DEFAULT else [size])),
        caption,
        columns,
        shown,
        findings(rows, robot, score, lambda row: str(row.label)),
    )


def _cells(columns: tuple[Column, ...], part: pd.DataFrame) -> tuple[Cell, ...]:
    by_split = pd.Series({split: row for split, (_, row) in zip(part.split, part.iterrows())})
    return tuple(column.read(by_split) for column in columns)


def _equivariant(by_split: pd.Series) -> Cell:
    claim = "yes" if by_split.iloc[0].equivariant else "no"
    return Cell(claim, claim)


def _split_column(metric: str, split: str, better: str) -> Column:
    """One split's `metric` across a table's models, each cell leading to its entry page."""
    read = mean_ci(metric)

    def cell(by_split: pd.Series) -> Cell:
        if split not in by_split:
            return Cell("-", "")
        row = by_split[split]
        best = metric == RMSE and str(row.rank_band).split("-")[0] == "1"
        return replace(read(row), best=best, link=names.entry_page(row_key(row)))

    name = metric if metric != RMSE else "test RMSE"
    return Column(
        f"{metric}--{split}",
        f"{split}: {name}, mean [95 % bootstrap interval] over seeds.",
        True,
        cell,
        label=split if metric == RMSE else f"{metric} · {split}",
        better=better,
    )

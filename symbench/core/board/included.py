"""Other boards' records beside one's own (`symbench leaderboard --include-board DIR`): a
plugin author's private model ranked among the published entries, in the same tables.

A board is a folder with a `records/` folder (the published `leaderboards/`), or a folder of
records itself. One's own record of a run (same key) is shown in place of a board's: a re-run
of a published model sits in the table once, as the author ran it, and the count of runs
replaced is said. Everything else is `aggregate`'s as for one folder: records of one dataset
id made on other data or another preset are refused, so a private model is only ever ranked
against runs on the same data and budgets.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from pathlib import Path

from symbench.core.board.leaderboard import RECORDS, load_records
from symbench.core.runs.results import RecordV1


def board_folder(board: Path) -> Path:
    """The folder holding `board`'s records: its `records/` when it has one, else itself."""
    return board / RECORDS if (board / RECORDS).is_dir() else board


def is_one_of(folder: Path, boards: Sequence[Path]) -> bool:
    """Whether `folder` is one of `boards` (or the board whose `records/` is one of them):
    tables written there would show one's own records as that board's."""
    taken = {b.resolve() for b in boards} | {
        b.resolve().parent for b in boards if b.name == RECORDS
    }
    return folder.resolve() in taken


def with_boards(
    results: Path, boards: Sequence[Path], report: Callable[[str], None] = lambda m: None
) -> list[tuple[Path, RecordV1]]:
    """The records under `results` and those of each board of `boards` whose run is not
    already among them (own first, then the boards in order); `report` hears what each board
    added and how many of its runs were already there."""
    records = load_records(results)
    keys = {record.key() for _, record in records}
    for board in boards:
        theirs = load_records(board_folder(board))
        added = [(p, r) for p, r in theirs if r.key() not in keys]
        keys |= {r.key() for _, r in added}
        known = len(theirs) - len(added)
        earlier = f" ({known} of its runs shown as the records before it have them)"
        report(f"included {len(added)} records of {board}" + (earlier if known else ""))
        records += added
    return records

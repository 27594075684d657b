"""The leaderboard as a static site (`symbench leaderboard --html DIR`): plain files that
need no server and no network, opened from disk or put on any static host.

Pages (file names in `names`): `index.html` is the overview, per robot, dataset, protocol
and size (`board.sizes`: default first, then each matched parameter count) a model x split
table of the headline metrics with the findings in words and the board page's plots
(`overview`, of default sizes), then what each split and score means; a board page per
(robot, dataset) holds a sortable, filterable table per protocol, size and split and the
plots; an entry page per table row (dataset, protocol, size, split, model, variant, backend)
shows each
seed's provenance, verification status and the commands that reproduce it; `compare.html`
shows the rows chosen on the board pages side by side (their ids in its URL, their numbers
in a script beside it, `compare`). The numbers are `leaderboard.aggregate`'s, so the site
and the Markdown board never disagree. The same records give the same bytes: nothing
depends on the time of the build or on the order of the files.

With `clips` (a results folder holding the runs' checkpoints) each board page also shows
clips of the closed loop, the best and the worst model climbing beside the expert (`clips`);
a clip whose checkpoint is gone is kept from the site being replaced when it shows the same
record and network.

The site is built whole in a staging folder beside DIR and put in its place, so a failure
leaves the old site as it was; a non-empty DIR that no build made is refused, not replaced.
"""

from __future__ import annotations

import shutil
from pathlib import Path

import pandas as pd

from symbench.core.board.leaderboard import aggregate, load_records
from symbench.core.board.site.clips import ClipPlan, clip_plan, draw_clips
from symbench.core.board.site.names import MARKER
from symbench.core.board.site.overview import overviews
from symbench.core.board.site.pages import board_pages, entry_pages
from symbench.core.board.site.plots import draw_plots
from symbench.core.board.site.render import Renderer
from symbench.core.board.sizes import default_size
from symbench.core.common.atomic import replace_folder, staging_folder
from symbench.core.common.errors import SymbenchError
from symbench.core.common.paths import writable_folder
from symbench.core.runs.results import RecordV1

__all__ = ["build_site"]


def build_site(
    results: Path,
    out: Path,
    board: Path = Path("leaderboards"),
    clips: Path | None = None,
    records: list[tuple[Path, RecordV1]] | None = None,
    without_clips: frozenset[str] = frozenset(),
) -> list[Path]:
    """Build the site of the records under `results` (or of `records`, when given: one's own
    with other boards', `included.with_boards`) into `out`; entry pages say whether the
    published `board` holds each record; with `clips`, the results folder whose checkpoints
    the clips load, board pages show them, but for the datasets in `without_clips`, whose
    pages say they were built without. Returns the files written, sorted."""
    records = load_records(results) if records is None else records
    table = aggregate(records)
    kept = out if (out / MARKER).is_file() else None  # an earlier build's clips
    planned = (
        None
        if clips is None
        else clip_plan(default_size(table), records, clips, kept, without_clips)
    )
    _check_replaceable(out)
    writable_folder(out, "site folder")
    staging = staging_folder(out)
    try:
        written = _build(records, table, board, staging, planned)
        replace_folder(staging, out)
    except BaseException:
        shutil.rmtree(staging, ignore_errors=True)
        raise
    return [out / path for path in sorted(written)]


def _check_replaceable(out: Path) -> None:
    if out.exists() and not out.is_dir():
        raise SymbenchError(f"{out} is a file; give --html a folder")
    if out.is_dir() and any(out.iterdir()) and not (out / MARKER).is_file():
        raise SymbenchError(
            f"{out} holds files that no site build wrote; give --html an empty or new folder"
        )


def _build(
    records: list[tuple[Path, RecordV1]],
    table: pd.DataFrame,
    board: Path,
    site: Path,
    clips: ClipPlan | None,
) -> list[str]:
    renderer = Renderer(site)
    renderer.static()
    boards = board_pages(table)
    plots = {}
    for page in boards:
        shown = default_size(table)  # a plot's series would mix sizes
        rows = shown[(shown.robot == page.robot) & (shown.dataset == page.dataset)]
        plots[page.path] = draw_plots(rows, page.robot, page.dataset, site)
        page_clips = None if clips is None else clips[page.robot, page.dataset]
        left_out = clips is not None and page_clips is None
        drawn = None if clips is None else draw_clips(page_clips or (), site)
        renderer.board(page, plots[page.path], drawn, left_out)
    entries = entry_pages(boards, records, board)
    for entry in entries:
        renderer.entry(entry)
    renderer.compare(entries)
    renderer.index(overviews(table, records), plots, boards, records=len(records))
    (site / MARKER).write_text("built by `symbench leaderboard --html`; replaced whole\n")
    return [*renderer.written, MARKER]

"""The compare page's data: every entry's headline metrics, written at build time as a
script (`names.ENTRY_DATA`) that compare.html loads with <script src>, since a browser
blocks fetch() of a file:// URL. Keys sorted, so the same records give the same bytes."""

from __future__ import annotations

import json
from collections.abc import Iterable

from symbench.core.board.site.pages import EntryPage
from symbench.core.board.sizes import titled


def entry_data(entries: Iterable[EntryPage]) -> bytes:
    """`window.SYMBENCH_ENTRIES`: entry id -> what compare.html shows of it, its metrics in
    the board's column order (the headline first), each with its direction of better."""
    data = {
        page.row.id: {
            "title": titled(
                f"{page.key.model} ({page.key.variant}, {page.key.backend})", page.key.size
            ),
            "robot": page.robot,
            "dataset": page.key.dataset,
            "protocol": page.key.protocol,
            "split": page.key.split,
            "entry": page.path,
            "board": page.board,
            "metrics": [
                [column.name, cell.shown, column.better]
                for column, cell in zip(page.columns, page.row.cells, strict=True)
            ],
        }
        for page in entries
    }
    text = json.dumps(data, sort_keys=True, ensure_ascii=False, indent=1)
    return f"window.SYMBENCH_ENTRIES = {text};\n".encode()

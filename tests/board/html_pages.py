"""The site's pages read back with the standard library's HTML parser, as a test sees them:
links, element ids, texts by class, the tables' captions, and the board tables (a row per
model group, each cell's data-value and text) by the id of the section around them."""

from __future__ import annotations

from collections import defaultdict
from dataclasses import dataclass, field
from html.parser import HTMLParser
from pathlib import Path

VOID = {"meta", "link", "img", "br", "hr", "input"}


@dataclass
class Cell:
    value: str | None
    text: str = ""
    link: str | None = None  # the href of a link in the cell
    best: bool = False  # marked as in the best rank band


@dataclass
class Row:
    model: str
    cells: list[Cell] = field(default_factory=list)


@dataclass
class Table:
    columns: list[str] = field(default_factory=list)
    better: dict[str, str] = field(default_factory=dict)  # a header's data-better, by column
    rows: list[Row] = field(default_factory=list)

    def cell(self, row: Row, column: str) -> Cell:
        return row.cells[self.columns.index(column)]

    def values(self, column: str) -> list[str | None]:
        return [self.cell(row, column).value for row in self.rows]


@dataclass
class Page:
    links: list[str] = field(default_factory=list)  # every href and src
    ids: set[str] = field(default_factory=set)
    texts: dict[str, list[str]] = field(default_factory=lambda: defaultdict(list))  # by class
    tables: dict[str, Table] = field(default_factory=dict)  # by the enclosing section's id
    options: list[str] = field(default_factory=list)  # the model filter's boxes' values
    captions: list[str] = field(default_factory=list)  # the tables' captions, in order


class _Reader(HTMLParser):
    def __init__(self) -> None:
        super().__init__(convert_charrefs=True)
        self.page = Page()
        self._open: list[tuple[str, str | None, list[str]]] = []  # tag, class, text
        self._sections: list[str] = []
        self._table: Table | None = None
        self._cell: Cell | None = None
        self._caption: list[str] | None = None

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        a = dict(attrs)
        self.page.links += [a[k] or "" for k in ("href", "src") if k in a]
        if a.get("id"):
            self.page.ids.add(a["id"] or "")
        if tag == "section":
            self._sections.append(a.get("id") or "")
        if tag == "input" and a.get("name") == "model":
            self.page.options.append(a.get("value") or "")
        if tag == "caption":
            self._caption = []
        if tag == "table" and "board" in (a.get("class") or "").split():
            self._table = self.page.tables[self._sections[-1] if self._sections else ""] = Table()
        if self._table is not None:
            if tag == "th" and "data-column" in a:
                self._table.columns.append(a["data-column"] or "")
                self._table.better[a["data-column"] or ""] = a.get("data-better") or ""
            elif tag == "tr" and "data-model" in a:
                self._table.rows.append(Row(a["data-model"] or ""))
            elif tag == "td":
                self._cell = Cell(a.get("data-value"), best="best" in (a.get("class") or ""))
                self._table.rows[-1].cells.append(self._cell)
            elif tag == "a" and self._cell is not None:
                self._cell.link = a.get("href")
        if tag not in VOID:
            self._open.append((tag, a.get("class"), []))

    def handle_endtag(self, tag: str) -> None:
        while self._open:
            open_tag, css_class, parts = self._open.pop()
            if css_class:
                self.page.texts[css_class].append(" ".join(" ".join(parts).split()))
            if open_tag == tag:
                break
        if tag == "section":
            self._sections.pop()
        elif tag == "table":
            self._table = None
        elif tag == "td":
            self._cell = None
        elif tag == "caption" and self._caption is not None:
            self.page.captions.append(" ".join("".join(self._caption).split()))
            self._caption = None

    def handle_data(self, data: str) -> None:
        for _, _, parts in self._open:
            parts.append(data)
        if self._cell is not None:
            self._cell.text += data
        if self._caption is not None:
            self._caption.append(data)


def read_page(path: Path) -> Page:
    reader = _Reader()
    reader.feed(path.read_text())
    reader.close()
    return reader.page

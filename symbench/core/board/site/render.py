"""The pages as HTML: Jinja2 templates from the package, autoescaped (every record field is
text to show, never markup), laid out the same for the same data, byte for byte."""

from __future__ import annotations

from importlib.resources import files
from pathlib import Path
from typing import Any

from jinja2 import Environment, PackageLoader, StrictUndefined, select_autoescape

from symbench.core.board.cells import count
from symbench.core.board.site import glossary, names
from symbench.core.board.site.clips import Clip
from symbench.core.board.site.columns import BEST, EXPLAINED
from symbench.core.board.site.compare import entry_data
from symbench.core.board.site.overview import DatasetOverview
from symbench.core.board.site.pages import BoardPage, EntryPage
from symbench.core.board.site.plots import Plot


def environment() -> Environment:
    env = Environment(
        loader=PackageLoader("symbench.core.board.site", "templates"),
        autoescape=select_autoescape(["html"]),
        undefined=StrictUndefined,  # a misspelt field fails the build, not the page
        trim_blocks=True,
        lstrip_blocks=True,
        keep_trailing_newline=True,
    )
    env.filters["count"] = count  # '3 datasets', '1 seed'
    env.globals.update(EXPLAINED=EXPLAINED, BEST=BEST)
    return env


class Renderer:
    """Writes the site's files under `site` and remembers them, relative to it."""

    def __init__(self, site: Path) -> None:
        self.site = site
        self.env = environment()
        self.written: list[str] = []

    def _write(self, path: str, data: bytes) -> None:
        target = self.site / path
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_bytes(data)
        self.written.append(path)

    def _page(self, template: str, path: str, **context: Any) -> None:
        # pages below the root reach static files and other pages through ../
        root = "../" * path.count("/")
        html = self.env.get_template(template).render(root=root, names=names, **context)
        self._write(path, html.encode())

    def static(self) -> None:
        source = files("symbench.core.board.site") / "static"
        for name in names.STATIC:
            self._write(names.static_file(name), (source / name).read_bytes())

    def index(
        self,
        overviews: list[DatasetOverview],
        plots: dict[str, tuple[Plot, ...]],
        boards: list[BoardPage],
        records: int,
    ) -> None:
        """The overview first; `plots` by board page, drawn for the board pages."""
        splits = [t.split for b in boards for s in b.sections for t in s.tables]
        columns = [c.name for b in boards for c in b.columns]
        self._page(
            "index.html",
            names.INDEX,
            overviews=overviews,
            plots=plots,
            boards={b.path: b for b in boards},
            models=sorted({m for b in boards for m in b.models}),
            records=records,
            groups=sum(len(t.rows) for b in boards for s in b.sections for t in s.tables),
            splits=glossary.splits(splits),
            scores=glossary.scores(columns),
        )

    def compare(self, entries: list[EntryPage]) -> None:
        """compare.html and the data its script reads."""
        self._write(names.ENTRY_DATA, entry_data(entries))
        self._page("compare.html", names.COMPARE)

    def board(
        self,
        page: BoardPage,
        plots: tuple[Plot, ...],
        clips: tuple[Clip, ...] | None = None,
        clips_left_out: bool = False,
    ) -> None:
        """`clips` None: a site built without clips (no section for them); `clips_left_out`:
        this page built without them in a site with clips (`--without-clips`)."""
        self._page(
            "board.html",
            page.path,
            page=page,
            plots=plots,
            clips=clips,
            clips_left_out=clips_left_out,
        )
        self.written += [p.path for p in plots if p.path is not None]
        self.written += [c.path for c in clips or ()]

    def entry(self, page: EntryPage) -> None:
        self._page("entry.html", page.path, page=page)

"""Where each file of the site lives, relative to its root: one definition, so that the
links of every page and the files written agree."""

from __future__ import annotations

import re
from typing import NamedTuple

from symbench.core.board.sizes import DEFAULT, titled

INDEX = "index.html"
COMPARE = "compare.html"  # entries side by side, chosen by the ids in its URL
ENTRY_DATA = "data/entries.js"  # their numbers, a script: fetch() of a file:// URL is blocked
# copied from the package's static/ into the site's static/
STATIC = ("site.css", "site.js", "compare.js", "entry.css")
MARKER = ".symbench-site"  # marks a folder as a site that a new build may replace whole
_UNSAFE = re.compile(r"[^A-Za-z0-9._-]+")
_NOT_IN_ID = re.compile(r"[^A-Za-z0-9_-]+")  # '.' too: an id is also a CSS selector


class GroupKey(NamedTuple):
    """A row of a board table: the runs averaged over seeds (as `leaderboard.aggregate`)."""

    dataset: str
    protocol: str
    split: str
    model: str
    variant: str
    backend: str
    size: str = DEFAULT  # `board.sizes`: 'default' or 'matched N'

    @property
    def section(self) -> str:
        """Its table's protocol and size in words: 'converge protocol', with ', matched at
        100 000 parameters' for a matched size."""
        return titled(f"{self.protocol} protocol", self.size)

    @property
    def parts(self) -> tuple[str, ...]:
        """What names it: the default size is left out, so default-size names stay as they
        were before sizes were kept apart."""
        return tuple(self) if self.size != DEFAULT else tuple(self)[:-1]


def slug(*parts: str) -> str:
    """`parts` as one file name: letters, digits, '.', '_' and '-' only, never hidden. Record
    fields are safe identifiers already; this keeps any other name from leaving the site."""
    return "__".join(_UNSAFE.sub("-", part).lstrip(".") or "-" for part in parts)


def board_page(robot: str, dataset: str) -> str:
    return f"boards/{slug(robot, dataset)}.html"


def plot_file(robot: str, dataset: str, plot: str) -> str:
    return f"boards/{slug(robot, dataset)}-{slug(plot)}.svg"


def clip_file(robot: str, dataset: str, role: str, model: str) -> str:
    return f"clips/{slug(robot, dataset)}-{slug(role)}-{slug(model)}.webp"


def entry_id(key: GroupKey) -> str:
    """A row's id in compare links: the name of its entry page."""
    return slug(*key.parts)


def entry_page(key: GroupKey) -> str:
    return f"entries/{entry_id(key)}.html"


def static_file(name: str) -> str:
    return f"static/{name}"


def anchor(*parts: str) -> str:
    """An element id for a section of a page, e.g. `converge--fraction-0-5`."""
    return "--".join(_NOT_IN_ID.sub("-", part) for part in parts)

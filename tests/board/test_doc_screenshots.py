"""The documentation's screenshots show the board that is committed: each carries the dataset
ids of the board it was taken of (`docs/images/take_screenshots.py`), and a board on other
data (dataset v7, say) makes this fail until `make screenshots` retakes them."""

from __future__ import annotations

import json
import re
from pathlib import Path

from PIL import Image

ROOT = Path(__file__).resolve().parents[2]
IMAGES = ROOT / "docs" / "images"
DOCS = (ROOT / "docs" / "leaderboard-site.md").read_text()


def board_datasets() -> str:
    records = (ROOT / "leaderboards" / "records").glob("*.json")
    return ",".join(sorted({json.loads(p.read_text())["dataset"]["id"] for p in records}))


def test_every_screenshot_shows_the_committed_boards_datasets():
    shots = sorted(IMAGES.glob("*.png"))
    assert shots
    for shot in shots:
        with Image.open(shot) as image:
            taken_of = image.text.get("symbench-datasets")  # type: ignore[attr-defined]
        assert taken_of == board_datasets(), f"{shot.name} shows {taken_of}: make screenshots"


def test_the_site_docs_show_each_screenshot_and_only_those():
    shown = set(re.findall(r"\(images/([^)]+\.png)\)", DOCS))
    assert shown == {p.name for p in IMAGES.glob("*.png")}

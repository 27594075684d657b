"""Retakes the documentation's screenshots of the committed site (`make screenshots`): the
overview and one entry page, each at a desktop width and at 420 px, the first screen a
visitor sees. Each PNG carries the board's dataset ids in a text chunk (`symbench-datasets`),
so that tests/board/test_doc_screenshots.py fails once the board moves to other data and the
pictures show a board that is gone.

Needs the system's Chromium (Debian's `chromium`) for Playwright, as the browser tests do.
"""

from __future__ import annotations

import io
import json
import shutil
from pathlib import Path

from PIL import Image, PngImagePlugin
from playwright.sync_api import sync_playwright

ROOT = Path(__file__).resolve().parents[2]
SITE = ROOT / "leaderboards" / "site"
IMAGES = ROOT / "docs" / "images"
# hexa's sdnn on iid, on whichever dataset version the board is on (the newest if several)
ENTRY = (
    sorted(SITE.glob("entries/hexa-climb-small-v*__converge__iid__sdnn__acc__torch.html"))[-1]
    .relative_to(SITE)
    .as_posix()
)
SHOTS = {  # file -> (page, viewport width)
    "site-overview.png": ("index.html", 1400),
    "site-overview-420px.png": ("index.html", 420),
    "site-entry-page.png": (ENTRY, 1400),
    "site-entry-page-420px.png": (ENTRY, 420),
}
HEIGHT = 900  # the first screen


def board_datasets() -> str:
    """The dataset ids of the committed board's records, sorted, comma-separated."""
    records = (ROOT / "leaderboards" / "records").glob("*.json")
    return ",".join(sorted({json.loads(p.read_text())["dataset"]["id"] for p in records}))


def main() -> None:
    chromium = shutil.which("chromium")
    if chromium is None:
        raise SystemExit("needs the Debian package chromium (apt-get install chromium)")
    info = PngImagePlugin.PngInfo()
    info.add_text("symbench-datasets", board_datasets())
    with sync_playwright() as playwright:
        browser = playwright.chromium.launch(executable_path=chromium)
        for name, (page_path, width) in SHOTS.items():
            page = browser.new_page(viewport={"width": width, "height": HEIGHT})
            page.goto((SITE / page_path).as_uri())
            shot = Image.open(io.BytesIO(page.screenshot()))
            shot.save(IMAGES / name, pnginfo=info, optimize=True)
            page.close()
        browser.close()


if __name__ == "__main__":
    main()

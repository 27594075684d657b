"""The site in a real browser, opened from disk (file://) as a reader opens a downloaded
site: the overview first on screen (also 420 px wide, without sideways scrolling of the
page), sorting (best first), the sticky model column, the model filter and the view kept in
the address, the compare page, a model's link to its entry page, the plots and the styles
load, no script error; screenshots of a board page and an entry page are kept as artifacts
(test-artifacts/, or $SYMBENCH_TEST_ARTIFACTS). Slow: `pytest -m slow tests/board`.

The browser is headless Chromium driven by Playwright, which is given the system's Chromium
(Debian package `chromium`): Playwright cannot download its own browsers here. The session
fixture installs the package with apt-get when it is missing, and fails, never skips, when
that does not work."""

from __future__ import annotations

import os
from collections.abc import Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any
from urllib.parse import parse_qs, urlsplit

import numpy as np
import pytest
from site_records import HEXA, LEGACY_MODEL, MODELS, SEEDS, SPLITS, metric, runs_of, table_id
from system_packages import ensure_chromium

from symbench.core.board.gap import HELD_OUT_SPLITS
from symbench.core.board.site.names import plot_file

pytestmark = pytest.mark.slow

ROOT = Path(__file__).resolve().parents[2]
ARTIFACTS = Path(os.environ.get("SYMBENCH_TEST_ARTIFACTS", ROOT / "test-artifacts"))
PNG = b"\x89PNG\r\n\x1a\n"
HEXA_PAGE = f"boards/hexa__{HEXA}.html"
# the fixture has a fraction split, closed-loop metrics and one held-out split (vs iid)
EXPECTED_PLOTS = {
    Path(plot_file("hexa", HEXA, plot)).name
    for plot in (
        "sample-efficiency",
        "closed-loop",
        *(
            "generalization-gap" + ("" if split == HELD_OUT_SPLITS[0] else f"-{split}")
            for split in HELD_OUT_SPLITS
            if split in SPLITS
        ),
    )
}


@pytest.fixture(scope="session")
def chromium() -> str:
    return ensure_chromium()


@pytest.fixture(scope="session")
def browser(chromium: str) -> Iterator[Any]:
    from playwright.sync_api import sync_playwright

    with sync_playwright() as playwright:
        # no sandbox: the tests may run as root, where Chromium's sandbox refuses to start
        launched = playwright.chromium.launch(
            executable_path=chromium, headless=True, args=["--no-sandbox"]
        )
        yield launched
        launched.close()


@dataclass
class Tab:
    """A browser page and the script errors it reported."""

    page: Any
    errors: list[str] = field(default_factory=list)


@pytest.fixture
def tab(browser: Any) -> Iterator[Tab]:
    page = browser.new_page(viewport={"width": 1400, "height": 900})
    opened = Tab(page)
    page.on("pageerror", lambda error: opened.errors.append(str(error)))
    page.on("console", lambda m: opened.errors.append(m.text) if m.type == "error" else None)
    yield opened
    page.close()


def shown_models(tab: Tab, table: str) -> list[str]:
    """The models of a table's visible rows, top to bottom."""
    rows = tab.page.locator(f"#{table} table.board tbody tr:visible")
    return rows.evaluate_all("rows => rows.map(row => row.dataset.model)")


def mean_of(results: Path, split: str, evaluator: str, name: str) -> dict[str, float]:
    return {
        m: float(np.mean(metric(runs_of(results, HEXA, "converge", split, m), evaluator, name)))
        for m in MODELS
    }


def screenshot(tab: Tab, name: str) -> Path:
    ARTIFACTS.mkdir(parents=True, exist_ok=True)
    path = ARTIFACTS / name
    tab.page.screenshot(path=str(path), full_page=True)
    assert path.read_bytes().startswith(PNG)
    return path


def test_sorting_orders_rows_by_the_records_means(tab, site, results):
    tab.page.goto((site / HEXA_PAGE).as_uri())
    for split in SPLITS:
        rmse = mean_of(results, split, "torque-error", "rmse")
        assert shown_models(tab, table_id("converge", split)) == sorted(
            MODELS, key=rmse.__getitem__
        )
    nrmse = mean_of(results, "iid", "torque-error", "nrmse")
    by_nrmse = sorted(MODELS, key=nrmse.__getitem__)
    assert by_nrmse != shown_models(tab, "converge--iid")  # sorting must change the order
    header = tab.page.locator('#converge--iid th[data-column="nrmse"]')
    header.click()
    assert shown_models(tab, "converge--iid") == by_nrmse
    assert header.get_attribute("aria-sort") == "ascending"
    header.click()
    assert shown_models(tab, "converge--iid") == by_nrmse[::-1]
    assert header.get_attribute("aria-sort") == "descending"
    tab.page.locator('#converge--iid th[data-column="model"]').click()
    assert shown_models(tab, "converge--iid") == sorted(MODELS)  # text: by name
    score = mean_of(results, "iid", "closed-loop", "pd_normalized_score")
    by_score = sorted(MODELS, key=score.__getitem__, reverse=True)
    assert by_score != shown_models(tab, "converge--iid")
    header = tab.page.locator('#converge--iid th[data-column="cl_score"]')
    header.click()  # higher is better: the first click puts the highest first
    assert shown_models(tab, "converge--iid") == by_score
    assert header.get_attribute("aria-sort") == "descending"
    unseen = mean_of(results, "unseen-heading", "torque-error", "rmse")
    # a click sorts its own table only
    assert shown_models(tab, "converge--unseen-heading") == sorted(MODELS, key=unseen.get)
    assert tab.errors == []


def test_the_model_filter_hides_other_models_and_the_address_keeps_the_view(tab, site):
    tab.page.goto((site / HEXA_PAGE).as_uri())
    every = tab.page.locator("table.board tbody tr")
    total = every.count()
    assert total == len(MODELS) * len(SPLITS) + 1  # and the schema-1 model's row
    for model in ("sdnn", "ffnn", LEGACY_MODEL):
        tab.page.locator(f'#model-filter input[value="{model}"]').uncheck()
    for split in SPLITS:
        assert shown_models(tab, table_id("converge", split)) == ["gnn"]
    assert shown_models(tab, "paper--iid") == []
    tab.page.locator('#converge--iid th[data-column="nrmse"]').click()
    query = parse_qs(urlsplit(tab.page.url).query)
    assert query["models"] == ["gnn"]
    assert query["sort"] == ["converge--iid:nrmse:ascending"]
    tab.page.reload()
    assert tab.page.locator("#model-filter input:checked").evaluate_all(
        "boxes => boxes.map(box => box.value)"
    ) == ["gnn"]
    assert tab.page.locator("table.board tbody tr:visible").count() == len(SPLITS)
    header = tab.page.locator('#converge--iid th[data-column="nrmse"]')
    assert header.get_attribute("aria-sort") == "ascending"  # the sort came back too
    for model in ("sdnn", "ffnn", LEGACY_MODEL):
        tab.page.locator(f'#model-filter input[value="{model}"]').check()
    assert tab.page.locator("table.board tbody tr:visible").count() == total
    assert "models" not in parse_qs(urlsplit(tab.page.url).query)  # all shown: no filter
    assert tab.errors == []


def test_the_model_column_stays_in_view_when_a_table_scrolls_sideways(tab, site):
    tab.page.set_viewport_size({"width": 600, "height": 900})
    tab.page.goto((site / HEXA_PAGE).as_uri())
    box = tab.page.locator("#converge--iid .table-scroll")
    assert box.evaluate("box => box.scrollWidth > box.clientWidth")  # it does scroll
    model = tab.page.locator("#converge--iid tr[data-model=sdnn] td.model")
    rmse = tab.page.locator("#converge--iid tr[data-model=sdnn] td").nth(2)
    before = model.bounding_box()["x"], rmse.bounding_box()["x"]
    box.evaluate("box => { box.scrollLeft = 200; }")
    after = model.bounding_box()["x"], rmse.bounding_box()["x"]
    assert after[0] == pytest.approx(before[0], abs=1)  # the model stays (to its border)
    assert after[1] < before[1] - 100  # the rest moves
    assert tab.errors == []


def plot_names(images) -> set[str]:
    """The plot files an image locator shows, by file name."""
    sources = images.evaluate_all("images => images.map(image => image.getAttribute('src'))")
    return {Path(urlsplit(source).path).name for source in sources}


def test_the_overview_shows_its_table_first(tab, site):
    tab.page.goto((site / "index.html").as_uri())
    first = tab.page.locator("main table").first
    assert (
        first.evaluate("table => table.closest('section').id")
        == f"overview--hexa--{HEXA}--converge"
    )
    top = first.bounding_box()["y"]
    assert top < 900 * 0.75  # within the first screen, not below an introduction
    assert shown_models(tab, f"overview--hexa--{HEXA}--converge") == ["sdnn", "gnn", "ffnn"]
    thumbnails = tab.page.locator(f"#dataset--hexa--{HEXA} figure.thumb img")
    assert plot_names(thumbnails) == EXPECTED_PLOTS
    for image in thumbnails.all():
        assert image.evaluate("img => img.complete && img.naturalWidth > 0")
    screenshot(tab, "site-index-page.png")
    assert tab.errors == []


def test_the_overview_fits_a_narrow_screen(browser, site):
    page = browser.new_page(viewport={"width": 420, "height": 900})
    errors: list[str] = []
    page.on("pageerror", lambda error: errors.append(str(error)))
    page.goto((site / "index.html").as_uri())
    assert page.evaluate("document.documentElement.scrollWidth") <= 420
    assert page.locator("main table").first.bounding_box()["y"] < 900
    page.screenshot(path=str(ARTIFACTS / "site-index-420px.png"), full_page=False)
    page.close()
    assert errors == []


def test_the_compare_page_shows_the_chosen_entries_side_by_side(tab, site, results):
    tab.page.goto((site / HEXA_PAGE).as_uri())
    for model in ("sdnn", "ffnn"):
        tab.page.locator(f"#converge--iid tr[data-model={model}] input.compare").check()
    assert tab.page.locator("#compare-count").inner_text() == "2 chosen"
    tab.page.locator("#compare-link").click()
    tab.page.wait_for_load_state()
    assert urlsplit(tab.page.url).path.endswith("/compare.html")
    headers = tab.page.locator("table.compare thead th[data-entry]")
    assert headers.evaluate_all("cells => cells.map(cell => cell.dataset.entry)") == [
        f"{HEXA}__converge__iid__{model}__acc__torch" for model in ("sdnn", "ffnn")
    ]
    rmse = tab.page.locator('table.compare tr[data-metric="rmse_Nm"] td')
    means = mean_of(results, "iid", "torque-error", "rmse")
    shown = [float(text.split(" ")[0]) for text in rmse.all_inner_texts()]
    assert shown == pytest.approx([means["sdnn"], means["ffnn"]], abs=5e-4)
    first_rows = tab.page.locator("table.compare tbody tr").evaluate_all(
        "rows => rows.slice(0, 3).map(row => row.dataset.metric)"
    )
    assert first_rows == ["rank", "rmse_Nm", "cl_score"]  # the headline first
    screenshot(tab, "site-compare-page.png")
    assert tab.errors == []


def test_plots_and_styles_load_from_disk(tab, site):
    tab.page.goto((site / HEXA_PAGE).as_uri())
    images = tab.page.locator("figure img")
    assert plot_names(images) == EXPECTED_PLOTS
    for image in images.all():
        assert image.evaluate("img => img.complete && img.naturalWidth > 0")
    cursor = tab.page.locator("table.board th button").first.evaluate(
        "button => getComputedStyle(button).cursor"
    )
    assert cursor == "pointer"  # site.css applies
    screenshot(tab, "site-board-page.png")
    assert tab.errors == []


def test_a_model_links_to_its_entry_page_with_the_records_provenance(tab, site, results):
    tab.page.goto((site / HEXA_PAGE).as_uri())
    tab.page.locator("#converge--iid tr[data-model=ffnn] a").click()
    tab.page.wait_for_load_state()
    assert tab.page.url.endswith(f"/entries/{HEXA}__converge__iid__ffnn__acc__torch.html")
    runs = runs_of(results, HEXA, "converge", "iid", "ffnn")
    for seed, run in zip(SEEDS, runs):
        section = tab.page.locator(f"#seed-{seed}")
        section.locator("details.fold summary").first.click()  # the provenance is folded
        shown = section.inner_text()
        assert run["dataset"]["content_hash"] in shown
        assert run["training"]["checkpoint_sha256"]["model.safetensors"] in shown
        assert section.locator("code.reproduce").inner_text() == (
            f"symbench run --model ffnn --robot hexa --split iid --seed {seed} --preset smoke "
            "--backend torch --variant acc --protocol converge "
            "--evaluators torque-error,closed-loop --max-steps 60"
        )
        assert section.locator("code.verify").inner_text() == (
            f"symbench verify {results / f'ffnn-iid-seed{seed}.json'}"
        )
        assert (
            section.locator(".verification")
            .inner_text()
            .startswith("Verification status: sealed, seal matches; not on the published board")
        )
    screenshot(tab, "site-entry-page.png")
    assert tab.errors == []


ENTRY_PAGE = f"entries/{HEXA}__converge__iid__ffnn__acc__torch.html"
# this page's height at 1280 px before the raw values were folded: 7,417 px (now ~1,900)
ENTRY_HEIGHT_PX = 3000


def page_width(tab: Tab) -> int:
    return tab.page.evaluate("document.documentElement.scrollWidth")


def test_an_entry_page_fits_a_phone_with_its_summary_on_the_first_screen(tab, site):
    tab.page.set_viewport_size({"width": 420, "height": 800})
    tab.page.goto((site / ENTRY_PAGE).as_uri())
    assert page_width(tab) <= 420
    summary = tab.page.locator("table.seeds")
    assert summary.is_visible()
    box = summary.bounding_box()
    assert box is not None and box["y"] < 800
    for details in tab.page.locator("details").all():  # the raw values too, once opened
        details.evaluate("details => { details.open = true }")
    assert tab.page.locator("pre.raw").first.is_visible()
    assert page_width(tab) <= 420
    screenshot(tab, "site-entry-page-420px.png")
    assert tab.errors == []


def test_an_entry_page_is_short_with_its_raw_values_folded_until_clicked(tab, site, results):
    tab.page.set_viewport_size({"width": 1280, "height": 900})
    tab.page.goto((site / ENTRY_PAGE).as_uri())
    assert tab.page.evaluate("document.documentElement.scrollHeight") < ENTRY_HEIGHT_PX
    assert tab.page.locator("details[open]").count() == 0
    provenance = tab.page.locator("#seed-0 details.fold").first
    table = provenance.locator("table.provenance").first
    assert not table.is_visible()
    provenance.locator("summary").click()
    assert provenance.evaluate("details => details.open")
    assert table.is_visible()
    (run, *_) = runs_of(results, HEXA, "converge", "iid", "ffnn")
    assert run["seal"] in provenance.inner_text()
    assert tab.errors == []

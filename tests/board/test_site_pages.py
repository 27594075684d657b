"""The static site built from records: every page there and linked, every link resolving
inside the site, the numbers the records' means, provenance and verification status on the
entry pages, the plots or the reason for their absence, and the same bytes on every build.
The pages are read back with the standard library's HTML parser (html_pages.py)."""

from __future__ import annotations

import json
import posixpath
import shutil
from pathlib import Path
from urllib.parse import urlsplit

import numpy as np
import pytest
from html_pages import Page, Table, read_page
from site_records import (
    HEXA,
    LEGACY_MODEL,
    MODELS,
    NONA,
    SEEDS,
    SPLITS,
    metric,
    runs_of,
    table_id,
)

from symbench.core.board.cells import metric_cell
from symbench.core.board.site import build_site
from symbench.core.runs.results import ResultRecord, write_record

SVG = b'<?xml version="1.0" encoding="utf-8" standalone="no"?>\n<!DOCTYPE svg'
HEXA_PAGE = f"boards/hexa__{HEXA}.html"
NONA_PAGE = f"boards/nona__{NONA}.html"


def pages(site: Path) -> dict[str, Page]:
    return {p.relative_to(site).as_posix(): read_page(p) for p in sorted(site.rglob("*.html"))}


def snapshot(folder: Path) -> dict[str, bytes]:
    return {
        p.relative_to(folder).as_posix(): p.read_bytes() for p in folder.rglob("*") if p.is_file()
    }


def broken_links(site: Path, page: str, links: list[str], read: dict[str, Page]) -> list[str]:
    """Links of `page` that leave the site or lead to no file (or no element) in it."""
    broken = []
    for link in links:
        parts = urlsplit(link)
        if parts.scheme or parts.netloc:
            broken.append(link)  # nothing may come from elsewhere: no server, no network
            continue
        target = (site / page).parent / parts.path if parts.path else site / page
        target = target.resolve()
        name = target.relative_to(site.resolve()).as_posix() if target.is_file() else None
        if name is None or (parts.fragment and parts.fragment not in read[name].ids):
            broken.append(link)
    return broken


def model_links(table: Table) -> dict[str, str]:
    return {row.model: table.cell(row, "model").link or "" for row in table.rows}


def test_every_page_is_built_and_linked(site):
    read = pages(site)
    boards = {name for name in read if name.startswith("boards/")}
    assert boards == {HEXA_PAGE, NONA_PAGE}
    assert boards <= {urlsplit(link).path for link in read["index.html"].links}
    groups = len(MODELS) * len(SPLITS) + 2  # and the schema-1 model, and nona's
    entries = {name for name in read if name.startswith("entries/")}
    assert len(entries) == groups
    linked = {
        posixpath.normpath(posixpath.join("boards", link))
        for board in boards
        for table in read[board].tables.values()
        for link in model_links(table).values()
    }
    assert linked == entries  # each row leads to its own entry page, none is left out
    for name in ("static/site.css", "static/site.js"):
        assert (site / name).stat().st_size > 0


def test_every_link_resolves_inside_the_site(site):
    read = pages(site)
    assert sum(len(page.links) for page in read.values()) > 50
    for name, page in read.items():
        assert broken_links(site, name, page.links, read) == [], name


def test_the_link_check_can_fail(site):
    read = pages(site)
    links = ["missing.html", "index.html#nowhere", "https://cdn.example.org/x.js", "index.html"]
    assert broken_links(site, "index.html", links, read) == links[:3]


def test_tables_show_the_records_means_ranked_by_rmse(site, results):
    hexa = read_page(site / HEXA_PAGE)
    for split in SPLITS:
        table = hexa.tables[table_id("converge", split)]
        expected = {}
        for model in MODELS:
            runs = runs_of(results, HEXA, "converge", split, model)
            assert [r["seed"] for r in runs] == list(SEEDS)
            expected[model] = np.mean(metric(runs, "torque-error", "rmse"))
        assert [row.model for row in table.rows] == sorted(expected, key=expected.__getitem__)
        assert table.values("rank") == ["1", "2", "3"]
        for row in table.rows:
            runs = runs_of(results, HEXA, "converge", split, row.model)
            for column, name in (("rmse_Nm", "rmse"), ("nrmse", "nrmse")):
                values = metric(runs, "torque-error", name)
                cell = table.cell(row, column)
                assert float(cell.value or "nan") == pytest.approx(np.mean(values), rel=1e-12)
                # three seeds: the 95 % bootstrap interval is their range
                assert cell.text == metric_cell(np.mean(values), min(values), max(values))
            assert table.cell(row, "seeds").value == str(len(SEEDS))
            assert table.cell(row, "steps").value == str(np.mean([20 + 10 * s for s in SEEDS]))
            score = table.cell(row, "cl_score").value
            if split == "iid":
                scores = metric(runs, "closed-loop", "pd_normalized_score")
                assert float(score or "nan") == pytest.approx(np.mean(scores), rel=1e-12)
            else:
                assert score == ""  # no closed-loop record: an empty cell, sorted last


def test_protocols_have_their_own_tables_and_the_filter_lists_the_models(site, results):
    hexa = read_page(site / HEXA_PAGE)
    assert sorted(hexa.tables) == sorted([*(table_id("converge", s) for s in SPLITS), "paper--iid"])
    legacy = hexa.tables["paper--iid"]
    assert [row.model for row in legacy.rows] == [LEGACY_MODEL]
    runs = runs_of(results, HEXA, "paper", "iid", LEGACY_MODEL)
    assert float(legacy.cell(legacy.rows[0], "rmse_Nm").value or "nan") == pytest.approx(
        np.mean(metric(runs, "torque-error", "rmse"))
    )
    assert legacy.cell(legacy.rows[0], "steps").value == ""  # schema 1 kept no steps
    assert hexa.options == ["", *sorted([*MODELS, LEGACY_MODEL])]
    assert read_page(site / NONA_PAGE).options == ["", "sdnn"]


def test_plots_are_drawn_or_their_absence_explained(site):
    hexa, nona = read_page(site / HEXA_PAGE), read_page(site / NONA_PAGE)
    images = sorted(link for link in hexa.links if link.endswith(".svg"))
    assert images == [
        f"../boards/hexa__{HEXA}-closed-loop.svg",
        f"../boards/hexa__{HEXA}-sample-efficiency.svg",
    ]
    for image in images:
        assert (site / "boards" / image).read_bytes().startswith(SVG)
    assert not any(link.endswith(".svg") for link in nona.links)
    no_gap = (
        "No plot: no model has records of both unseen-rotation and its control or iid on "
        "this dataset."
    )
    assert nona.texts["absent"] == [
        "No plot: no record of a fraction-F split on this dataset.",
        "No plot: no record on this dataset has closed-loop metrics (run --full).",
        no_gap,
    ]
    assert hexa.texts["absent"] == [no_gap]


def entry(site: Path, split: str, model: str) -> Page:
    link = model_links(read_page(site / HEXA_PAGE).tables[table_id("converge", split)])[model]
    return read_page(site / "boards" / link)


def test_entry_pages_show_each_seeds_provenance_and_how_to_reproduce_it(site, results):
    page = entry(site, "iid", "ffnn")
    runs = runs_of(results, HEXA, "converge", "iid", "ffnn")
    text = " ".join(page.texts["provenance"])
    for run in runs:
        assert run["dataset"]["content_hash"] in text
        assert run["training"]["checkpoint_sha256"]["model.safetensors"] in text
        assert run["seal"] in text
        assert run["model"]["plugin"]["source_sha256"] in text
    assert page.ids >= {f"seed-{s}" for s in SEEDS}
    assert page.texts["reproduce"] == [
        "symbench run --model ffnn --robot hexa --split iid --seed "
        f"{s} --preset smoke --backend torch --variant acc --protocol converge "
        "--evaluators torque-error,closed-loop --max-steps 60"  # twice the preset's budget
        for s in SEEDS
    ]
    assert page.texts["verify"] == [
        f"symbench verify {results / f'ffnn-iid-seed{s}.json'}" for s in SEEDS
    ]
    assert page.texts["verification"] == [
        "Verification status: sealed, seal matches; not on the published board (no "
        f"{site.parent / 'board' / 'records' / ResultRecord.model_validate(r).key()}.json)"
        for r in runs
    ]
    gnn = entry(site, "iid", "gnn").texts["reproduce"]
    assert all(command.endswith(" --size latent=64") for command in gnn)  # its override


def test_schema_1_records_are_shown_but_not_verified(site, results):
    link = model_links(read_page(site / HEXA_PAGE).tables["paper--iid"])[LEGACY_MODEL]
    page = read_page(site / "boards" / link)
    for seed, status in zip(SEEDS, page.texts["verification"]):
        path = results / f"{LEGACY_MODEL}-seed{seed}.json"
        assert status.startswith(
            f"Verification status: not verified: {path}: record is not sealed (schema 1)"
        )
    assert "plugin not recorded (schema 1)" in page.texts["provenance"][2]
    assert page.texts["reproduce"][0].endswith("--protocol paper --evaluators torque-error")


def test_entry_pages_say_whether_the_published_board_holds_the_record(results, board, tmp_path):
    runs = {p.name: json.loads(p.read_text()) for p in results.glob("sdnn-iid-seed*.json")}
    keys = {s: ResultRecord.model_validate(runs[f"sdnn-iid-seed{s}.json"]).key() for s in SEEDS}
    (board / "records").mkdir(parents=True)
    shutil.copy(results / "sdnn-iid-seed0.json", board / "records" / f"{keys[0]}.json")
    other = runs["sdnn-iid-seed1.json"]
    other["metrics"]["torque-error"]["rmse"] *= 2  # another record of the same run
    write_record(other, board / "records" / f"{keys[1]}.json")
    build_site(results, tmp_path / "site", board)
    statuses = entry(tmp_path / "site", "iid", "sdnn").texts["verification"]
    published = board / "records"
    assert statuses == [
        "Verification status: sealed, seal matches; on the published board "
        f"({published / keys[0]}.json)",
        "Verification status: sealed, seal matches; not on the published board: "
        f"{published / keys[1]}.json is a different record of this run",
        "Verification status: sealed, seal matches; not on the published board (no "
        f"{published / keys[2]}.json)",
    ]


def test_building_twice_gives_the_same_bytes(site, results, board, tmp_path):
    first = snapshot(site)
    assert len(first) > 15
    build_site(results, tmp_path / "again", board)
    assert snapshot(tmp_path / "again") == first
    build_site(results, site, board)  # over the previous build
    assert snapshot(site) == first


def test_a_rebuild_replaces_the_site_whole(site, results, board, tmp_path):
    (site / "entries" / "stale.html").write_text("from an older build")
    (results / "nona-sdnn-seed0.json").unlink()
    written = build_site(results, site, board)
    assert not (site / "entries" / "stale.html").exists()
    assert sorted(p for p in site.rglob("*") if p.is_file()) == written
    assert [p.name for p in tmp_path.iterdir() if p.name.startswith(".")] == []  # no staging

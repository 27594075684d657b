"""The static site built from records: every page there and linked, every link resolving
inside the site, the numbers the records' means, provenance and verification status on the
entry pages, the plots or the reason for their absence, and the same bytes on every build.
The pages are read back with the standard library's HTML parser (html_pages.py)."""

from __future__ import annotations

import html
import json
import posixpath
import re
import shutil
from pathlib import Path
from urllib.parse import urlsplit

import numpy as np
import pytest
from html_pages import Page, Table, read_page
from scipy import stats
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

from symbench.core.board.cells import count, metric_cell
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
            score = table.cell(row, "cl_score").value
            assert table.columns[:4] == ["model", "rank", "rmse_Nm", "cl_score"]  # headline first
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
    assert hexa.options == sorted([*MODELS, LEGACY_MODEL])
    assert read_page(site / NONA_PAGE).options == ["sdnn"]


def test_plots_are_drawn_or_their_absence_explained(site):
    hexa, nona = read_page(site / HEXA_PAGE), read_page(site / NONA_PAGE)
    images = sorted(link for link in hexa.links if link.endswith(".svg"))
    assert images == [  # unseen-heading against iid: the fixture has no control-heading
        f"../boards/hexa__{HEXA}-closed-loop.svg",
        f"../boards/hexa__{HEXA}-generalization-gap-unseen-heading.svg",
        f"../boards/hexa__{HEXA}-sample-efficiency.svg",
    ]
    for image in images:
        assert (site / "boards" / image).read_bytes().startswith(SVG)
    assert not any(link.endswith(".svg") for link in nona.links)
    no_gap = "No plot: no model has records of both {} and its control or iid on this dataset."
    assert nona.texts["absent"] == [
        "No plot: no record of a fraction-F split on this dataset.",
        "No plot: no record on this dataset has closed-loop metrics (run --full).",
        no_gap.format("unseen-rotation"),
        no_gap.format("unseen-heading"),
    ]
    assert hexa.texts["absent"] == [no_gap.format("unseen-rotation")]


def entry(site: Path, split: str, model: str) -> Page:
    link = model_links(read_page(site / HEXA_PAGE).tables[table_id("converge", split)])[model]
    return read_page(site / "boards" / link)


def test_entry_pages_show_each_seeds_provenance_and_how_to_reproduce_it(site, results, board):
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
        f"{board / 'records' / ResultRecord.model_validate(r).key()}.json)"
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


def test_entry_pages_say_whether_the_published_board_holds_the_record(results, tmp_path):
    board = tmp_path / "board"
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


def test_building_twice_gives_the_same_bytes(site, results, board, tmp_path, own_copy):
    first = snapshot(site)
    assert len(first) > 15
    build_site(results, tmp_path / "again", board)
    assert snapshot(tmp_path / "again") == first
    earlier = own_copy(site)
    build_site(results, earlier, board)  # over the previous build
    assert snapshot(earlier) == first


def test_a_rebuild_replaces_the_site_whole(site, results, board, tmp_path, own_copy):
    site, results = own_copy(site), own_copy(results)
    (site / "entries" / "stale.html").write_text("from an older build")
    (results / "nona-sdnn-seed0.json").unlink()
    written = build_site(results, site, board)
    assert not (site / "entries" / "stale.html").exists()
    assert sorted(p for p in site.rglob("*") if p.is_file()) == written
    assert [p.name for p in tmp_path.iterdir() if p.name.startswith(".")] == []  # no staging


def test_columns_constant_over_a_table_are_folded_into_its_caption(site):
    hexa = read_page(site / HEXA_PAGE)
    iid = hexa.tables["converge--iid"]
    for folded in ("variant", "backend", "seeds", "steps", "stopped_by", "parameters"):
        assert folded not in iid.columns
    steps = metric_cell(30.0, 20.0, 40.0)  # every model: seeds 0-2 trained 20, 30, 40 steps
    said = (
        "converge protocol, split iid. Every row: variant acc, backend torch, cl_success "
        f"0.500, cl_rmse_rad 0.0200, parameters 1\u202f234, learning_rate 0.0005, steps {steps}, "
        "epochs 3.00, "
        "stopped_by patience 3, seeds 3"
    )
    assert hexa.captions[0] == " ".join(said.split())  # as the reader joins white space
    # no closed loop off iid: those columns are left out, not said to hold '-'
    assert "cl_success" not in hexa.captions[1]
    legacy = hexa.tables["paper--iid"]  # one row: nothing is folded
    assert {"variant", "backend", "seeds"} <= set(legacy.columns)


def test_headers_say_which_direction_is_better(site):
    table = read_page(site / HEXA_PAGE).tables["converge--iid"]
    assert table.better["rmse_Nm"] == table.better["nrmse"] == table.better["rank"] == "lower"
    assert table.better["cl_score"] == table.better["cl_held_s"] == "higher"
    legacy = read_page(site / HEXA_PAGE).tables["paper--iid"]
    assert table.better["model"] == legacy.better["epochs"] == legacy.better["seeds"] == ""
    text = (site / HEXA_PAGE).read_text()
    assert 'rmse_Nm <span class="better" aria-hidden="true">↓</span>' in text
    assert '<span class="visually-hidden">(higher is better)</span>' in text
    glossary = read_page(site / HEXA_PAGE).texts["glossary"][0]
    assert "cl_score ↑ Higher is better. Closed-loop score of the time held" in glossary


@pytest.mark.parametrize(
    ("mean", "low", "high", "shown"),
    [
        (0.0150, 0.0141, 0.0162, "0.0150 [0.0141, 0.0162]"),
        (10000.0, 10000.0, 10000.0, "10\u202f000"),  # no '1e+04', no empty interval
        (9667.0, 9000.0, 10240.0, "9\u202f667 [9\u202f000, 10\u202f240]"),
        (3.067e-07, 3.063e-07, 3.07e-07, "3.07 \u00d7 10⁻⁷ [3.06 \u00d7 10⁻⁷, 3.07 \u00d7 10⁻⁷]"),
        (0.5, np.nan, np.nan, "0.500"),  # one seed: no interval
        (1.312, 1.3121, 1.3123, "1.31 [1.31, 1.31]"),  # seeds differ: an interval, however narrow
        (np.nan, np.nan, np.nan, "-"),
    ],
)
def test_numbers_are_plain_decimals_to_significant_digits(mean, low, high, shown):
    assert metric_cell(mean, low, high) == shown


def test_counts_have_their_plural():
    assert [count(1, "dataset"), count(3, "dataset"), count(10000, "step")] == [
        "1 dataset",
        "3 datasets",
        "10\u202f000 steps",
    ]


def test_the_overview_comes_first_with_the_headline_of_every_dataset(site, results):
    index = read_page(site / "index.html")
    converge = index.tables[f"overview--hexa--{HEXA}--converge"]
    assert next(iter(index.tables)) == f"overview--hexa--{HEXA}--converge"  # first on the page
    assert converge.columns == [
        "model",
        "equivariant",
        *(f"rmse_Nm--{split}" for split in SPLITS),
        "cl_score--iid",  # the closed loop ran on iid only
    ]
    assert [row.model for row in converge.rows] == ["sdnn", "gnn", "ffnn"]  # rank on iid
    for row in converge.rows:
        assert converge.cell(row, "equivariant").text == ("yes" if row.model == "sdnn" else "no")
        for split in SPLITS:
            cell = converge.cell(row, f"rmse_Nm--{split}")
            rmse = metric(
                runs_of(results, HEXA, "converge", split, row.model), "torque-error", "rmse"
            )
            assert float(cell.value or "nan") == pytest.approx(np.mean(rmse), rel=1e-12)
            assert cell.best == (row.model == "sdnn")  # the records tell the three apart
            assert cell.link == (f"entries/{HEXA}__converge__{split}__{row.model}__acc__torch.html")
    assert index.tables[f"overview--nona--{NONA}--paper"].columns[2:] == ["rmse_Nm--iid"]
    boards = {urlsplit(link).path for link in index.links}
    assert {HEXA_PAGE, NONA_PAGE} <= boards  # the board pages stay linked


def test_the_findings_are_written_from_the_table(site, results):
    findings = read_page(site / "index.html").texts["findings"]
    rmse = {
        m: metric(runs_of(results, HEXA, "converge", "iid", m), "torque-error", "rmse")
        for m in ("sdnn", "gnn")
    }
    logs = np.log(rmse["sdnn"]) - np.log(rmse["gnn"])  # paired by seed
    half = stats.t.ppf(0.975, len(logs) - 1) * logs.std(ddof=1) / np.sqrt(len(logs))
    ratio = metric_cell(*np.exp([logs.mean(), logs.mean() - half, logs.mean() + half]), 2)
    sdnn, gnn = (metric_cell(np.mean(v), min(v), max(v)) for v in rmse.values())
    # sdnn is the equivariant one, gnn the best that is not (site_records)
    assert findings[0].startswith(
        f"On hexa iid, sdnn's test error is {ratio} \u00d7 gnn's ({sdnn} against {gnn} N m); a "
        "paired t-test over seeds tells them apart."
    )
    assert "Closed loop on iid: the highest cl_score is sdnn's" in findings[0]
    assert "Only sdnn has records here: nothing to compare it with." in findings[-1]


def test_the_overview_defines_each_split_and_score(site):
    text = " ".join(read_page(site / "index.html").texts["glossary"])
    assert "iid held-out trajectories of the same scenario distribution" in text
    assert "fraction-0.5 iid with 0.5 of its training trajectories (sample efficiency)" in text
    assert "cl_score Closed-loop score of the time held: 0 is the PD alone (the floor)" in text
    assert "rmse_Nm Test torque RMSE in N m" in text


def test_the_plots_alt_texts_say_which_model_is_best(site):
    def alts(page: Path) -> list[str]:
        return re.findall(r'<img src="[^"]*\.svg" alt="([^"]*)"', page.read_text())

    shown = alts(site / HEXA_PAGE)
    # sample efficiency, closed loop, unseen-heading's gap against iid; no unseen-rotation
    assert len(shown) == 3
    assert "sdnn (acc, torch, converge) has the lowest error at every fraction" in html.unescape(
        shown[0]
    )
    assert "The highest: sdnn (acc, torch)" in html.unescape(shown[1])
    assert set(shown) <= set(alts(site / "index.html"))  # the overview's thumbnails say it too


def test_the_compare_data_holds_every_entry_with_its_headline_first(site):
    script = (site / "data" / "entries.js").read_text()
    prefix = "window.SYMBENCH_ENTRIES = "
    assert script.startswith(prefix) and script.endswith(";\n")
    data = json.loads(script.removeprefix(prefix).removesuffix(";\n"))
    entries = {p.stem for p in (site / "entries").glob("*.html")}
    assert set(data) == entries
    ffnn = data[f"{HEXA}__converge__iid__ffnn__acc__torch"]
    assert ffnn["entry"] == f"entries/{HEXA}__converge__iid__ffnn__acc__torch.html"
    assert [m[0] for m in ffnn["metrics"][:3]] == ["rank", "rmse_Nm", "cl_score"]
    assert ffnn["metrics"][1][2] == "lower" and ffnn["metrics"][2][2] == "higher"
    assert (site / "compare.html").is_file()

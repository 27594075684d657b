"""`symbench leaderboard --html DIR` from the command line: the site instead of the Markdown,
both when --out is given too, and a one-line error, with nothing written, on bad input."""

from __future__ import annotations

import json

import pytest
from cli_invoke import error_line, invoke


@pytest.fixture
def workdir(tmp_path, monkeypatch):
    """An empty working folder, so that the default --out (leaderboards) would show."""
    folder = tmp_path / "work"
    folder.mkdir()
    monkeypatch.chdir(folder)
    return folder


def test_html_builds_the_site_instead_of_the_markdown(results, workdir):
    result = invoke("leaderboard", "--results", results, "--html", "site")
    assert result.exit_code == 0, result.output
    assert result.output.startswith("wrote site/index.html and ")
    assert (workdir / "site" / "index.html").is_file()
    assert sorted(p.name for p in workdir.iterdir()) == ["site"]  # no leaderboards/


def test_html_and_out_write_both(results, workdir):
    result = invoke("leaderboard", "--results", results, "--html", "site", "--out", "md")
    assert result.exit_code == 0, result.output
    assert (workdir / "site" / "index.html").is_file()
    assert (workdir / "md" / "hexa.md").is_file()
    assert "wrote md/hexa.md" in result.output


def test_board_option_names_the_published_board(results, workdir):
    result = invoke("leaderboard", "--results", results, "--html", "site", "--board", "pub")
    assert result.exit_code == 0, result.output
    page = next((workdir / "site" / "entries").glob("*__iid__sdnn__acc__torch.html"))
    assert "not on the published board (no pub/records/" in page.read_text()


def test_no_records_is_a_one_line_error(workdir):
    (workdir / "empty").mkdir()
    result = invoke("leaderboard", "--results", "empty", "--html", "site")
    assert error_line(result, 1) == "Error: no result records (*.json) under empty"
    assert not (workdir / "site").exists()


def test_an_unreadable_record_is_a_one_line_error(results, workdir, own_copy):
    results = own_copy(results)
    (results / "broken.json").write_text("{not json")
    result = invoke("leaderboard", "--results", results, "--html", "site")
    assert error_line(result, 1).startswith(f"Error: cannot read result record {results}/broken")
    assert not (workdir / "site").exists()


def test_an_edited_record_is_a_one_line_error(results, workdir, own_copy):
    results = own_copy(results)
    path = results / "sdnn-iid-seed0.json"
    record = json.loads(path.read_text())
    record["metrics"]["torque-error"]["rmse"] = 0.001  # better than measured
    path.write_text(json.dumps(record))
    result = invoke("leaderboard", "--results", results, "--html", "site")
    assert error_line(result, 1) == (
        f"Error: {path}: record does not match its seal (edited after it was written)"
    )
    assert not (workdir / "site").exists()


def test_a_folder_that_is_not_a_site_is_never_replaced(results, workdir):
    (workdir / "docs").mkdir()
    (workdir / "docs" / "notes.md").write_text("mine")
    result = invoke("leaderboard", "--results", results, "--html", "docs")
    assert error_line(result, 1) == (
        "Error: docs holds files that no site build wrote; give --html an empty or new folder"
    )
    assert [p.name for p in (workdir / "docs").iterdir()] == ["notes.md"]

"""Whatever one file among a board's genuine records holds (any bytes, or a record edited
field by field, sealed again or not), building the board's tables and site gives the board
or a one-line refusal, whether the file is among one's own records or an included board's
(`--include-board`); `publish --dry-run` names each record it refuses and writes nothing:
never an internal error."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest
from cli_invoke import invoke, refusal
from hypothesis import HealthCheck, event, given, settings
from hypothesis import strategies as st
from strategies import FILE_BYTES, edited

from symbench.core.runs.results import seal_of

RECORDS = Path(__file__).parents[2] / "leaderboards/archive/small-v6-superseded/records"
GENUINE = sorted(
    RECORDS.glob("hexa-climb-small-v6__small__iid__sd*nn__acc__torch__converge__seed*.json")
)
SHARED_FIXTURES = settings(suppress_health_check=[HealthCheck.function_scoped_fixture])


@pytest.fixture(scope="module")
def genuine() -> list[Path]:
    assert len(GENUINE) == 6, GENUINE  # sdnn and sdgnn, three seeds each
    return GENUINE


def odd_file(data: st.DataObject, genuine: list[Path]) -> bytes:
    """Any bytes, or one of the genuine records edited, sealed again or not."""
    if data.draw(st.booleans(), label="bytes"):
        return data.draw(FILE_BYTES)
    record = data.draw(edited(json.loads(genuine[0].read_text())))
    if isinstance(record, dict) and data.draw(st.booleans(), label="reseal"):
        record["seal"] = seal_of(record)
    return json.dumps(record).encode()


@SHARED_FIXTURES
@given(data=st.data())
def test_a_board_with_one_odd_file_builds_or_is_refused_in_one_line(tmp_path, genuine, data):
    results = tmp_path / "results"
    shutil.rmtree(results, ignore_errors=True)
    results.mkdir()
    for path in genuine:
        shutil.copy(path, results / path.name)
    (results / "odd.json").write_bytes(odd_file(data, genuine))
    out = tmp_path / "out"
    shutil.rmtree(out, ignore_errors=True)
    result = invoke(
        "leaderboard", "--results", results, "--out", out / "md", "--html", out / "site"
    )
    if result.exit_code == 0:
        event("built")
        assert (out / "site" / "index.html").is_file() and (
            out / "md" / "leaderboard.csv"
        ).is_file()
        return
    event("refused")
    assert "odd.json" in refusal(result)


@settings(SHARED_FIXTURES, max_examples=settings.default.max_examples // 5)  # builds a site each
@given(data=st.data())
def test_an_included_board_with_one_odd_file_builds_or_is_refused_in_one_line(
    tmp_path, genuine, data
):
    """The odd file among the records of a board ranked beside one's own (`--include-board`)."""
    results, board = tmp_path / "results", tmp_path / "board" / "records"
    for folder in (results, board):
        shutil.rmtree(folder, ignore_errors=True)
        folder.mkdir(parents=True)
    for path in genuine:
        shutil.copy(path, (results if "seed0" in path.name else board) / path.name)
    (board / "odd.json").write_bytes(odd_file(data, genuine))
    out = tmp_path / "out"
    shutil.rmtree(out, ignore_errors=True)
    result = invoke(
        "leaderboard", "--results", results, "--include-board", board.parent,
        "--out", out / "md", "--html", out / "site",
    )  # fmt: skip
    if result.exit_code == 0:
        event("built")
        assert (out / "site" / "index.html").is_file()
        return
    event("refused")
    assert "odd.json" in refusal(result)


@SHARED_FIXTURES
@given(data=st.data())
def test_publish_dry_run_over_an_odd_record_reports_it_and_writes_nothing(tmp_path, genuine, data):
    odd = tmp_path / "odd.json"
    odd.write_bytes(odd_file(data, genuine))
    board = tmp_path / "board"
    shutil.rmtree(board, ignore_errors=True)
    board.mkdir()
    result = invoke("publish", "--dry-run", "--to", board, odd, *genuine)
    assert list(board.iterdir()) == []  # a dry run writes nothing
    if result.exit_code == 0:
        event("accepted")
        return
    event("refused")
    assert refusal(result).startswith("Error: publish would refuse these records")
    refused = [line for line in result.stdout.splitlines() if line.startswith("refused: ")]
    named = [str(path) for path in (odd, *genuine)]  # odd.json, or a record it clashes with
    assert refused and all(any(p in line for p in named) for line in refused), result.stdout

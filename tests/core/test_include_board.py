"""`symbench leaderboard --include-board DIR`: a private model ranked beside a board's
published entries, in the same tables (issue 42, item 14)."""

from __future__ import annotations

from click.testing import CliRunner

from symbench.core.cli import build_cli
from symbench.core.runs.results import write_record


def board_and_mine(tmp_path, make_record):
    """A board (records/ beside its tables) with sdnn's three seeds; my folder with
    leg-mixer's three seeds and my own re-run of sdnn's seed 0."""
    for seed, rmse in enumerate([0.2, 0.3, 0.4]):
        record = make_record(model="sdnn", seed=seed, rmse=rmse)
        write_record(record, tmp_path / "board" / "records" / f"sdnn{seed}.json")
        write_record(make_record(model="leg-mixer", seed=seed), tmp_path / "mine" / f"m{seed}.json")
    write_record(make_record(model="sdnn", seed=0, rmse=0.9), tmp_path / "mine" / "sdnn0.json")
    return tmp_path / "board", tmp_path / "mine"


def leaderboard(*args):
    return CliRunner().invoke(build_cli(), ["leaderboard", *map(str, args)])


def test_my_model_is_ranked_beside_the_boards(tmp_path, make_record):
    board, mine = board_and_mine(tmp_path, make_record)
    out = tmp_path / "out"
    result = leaderboard("--results", mine, "--include-board", board, "--out", out)
    assert result.exit_code == 0, result.output
    assert f"included 2 records of {board} (1 of its runs shown as" in result.output
    table = (out / "hexa.md").read_text()
    assert "| leg-mixer | acc | torch | 3 |" in table
    assert "| sdnn | acc | torch | 3 |" in table
    csv = (out / "leaderboard.csv").read_text()
    assert ",sdnn,acc,torch,3,1234,0.0005,epoch-cap 3,0.533333," in csv  # (0.9 + 0.3 + 0.4) / 3


def test_a_folder_of_records_is_a_board_too(tmp_path, make_record):
    board, mine = board_and_mine(tmp_path, make_record)
    out = tmp_path / "out"
    result = leaderboard("--results", mine, "--include-board", board / "records", "--out", out)
    assert result.exit_code == 0, result.output
    assert "| sdnn |" in (out / "hexa.md").read_text()


def test_the_included_boards_tables_are_never_overwritten(tmp_path, make_record):
    board, mine = board_and_mine(tmp_path, make_record)
    for out in (board, board / "records"):
        result = leaderboard("--results", mine, "--include-board", board / "records", "--out", out)
        assert result.exit_code == 2 and "is an included board" in result.output
    assert sorted(p.name for p in board.iterdir()) == ["records"]

"""leaderboards/ holds exactly what the commands make from the records committed beside it."""

from __future__ import annotations

import os
import re
import subprocess
import sys
from pathlib import Path

import pytest
from click.testing import CliRunner
from cpu_features import WITHOUT_AVX512

from symbench.core.board.leaderboard import load_records
from symbench.core.board.publish import publish
from symbench.core.board.site import build_site
from symbench.core.cli import build_cli

ROOT = Path(__file__).resolve().parents[2]
BOARD = ROOT / "leaderboards"
SITE = BOARD / "site"
MADE = (".md", ".csv", ".png")


def _made_files(folder: Path) -> dict[str, bytes]:
    return {
        p.name: p.read_bytes()
        for p in folder.iterdir()
        if p.suffix in MADE and p.name != "README.md"
    }


# boards of their own beside the main one: ablations and studies, each with its records/
SIDE_BOARDS = sorted(
    folder
    for kind in ("ablations", "studies")
    if (BOARD / kind).is_dir()
    for folder in (BOARD / kind).iterdir()
    if (folder / "records").is_dir()
)


@pytest.mark.parametrize(
    "board", [BOARD, *SIDE_BOARDS], ids=["main", *(f.name for f in SIDE_BOARDS)]
)
def test_committed_tables_regenerate_identically(board, tmp_path):
    result = CliRunner().invoke(
        build_cli(), ["leaderboard", "--results", str(board / "records"), "--out", str(tmp_path)]
    )
    assert result.exit_code == 0, result.output
    made, committed = _made_files(tmp_path), _made_files(board)
    assert sorted(made) == sorted(committed)
    for name, content in made.items():
        assert content == committed[name], f"{board}/{name} is not what the records give"


@pytest.mark.parametrize("board", [BOARD, BOARD / "studies" / "asymmetry-v7"], ids=["main", "asym"])
def test_the_tables_and_plots_are_the_same_bytes_without_avx512(board, tmp_path):
    """The board (its log-scale plots and paired statistics) is the same bytes on a CPU
    without AVX-512 as on one with it: rebuilt in a process whose numpy cannot use those
    kernels, it is still the committed board, which the test above rebuilds in this process.
    On a CPU without AVX-512 both take the same path; on one with it (an Intel Xeon), nona's
    sample-efficiency PNG, drawn on matplotlib's own log scale on an AMD EPYC, passed here and
    failed the test above."""
    out = tmp_path / "board"
    subprocess.run(
        [
            sys.executable,
            "-m",
            "symbench",
            "leaderboard",
            "--results",
            str(board / "records"),
            "--out",
            str(out),
        ],
        env={**os.environ, **WITHOUT_AVX512, "MUJOCO_GL": "disable"},
        check=True,
        capture_output=True,
    )
    made, committed = _made_files(out), _made_files(board)
    assert sorted(made) == sorted(committed)
    for name, content in made.items():
        assert content == committed[name], f"{board}/{name} differs without AVX-512"


def _without_clips(page: str) -> str:
    """A board page as a build without clips writes it: the clips' link and section gone."""
    page = page.replace('\n· <a href="#clips">clips</a>', "")
    return re.sub(r'\n<section id="clips">.*?</section>', "", page, flags=re.S)


def test_the_committed_site_regenerates_from_the_records(tmp_path, monkeypatch):
    """leaderboards/site/ is `symbench leaderboard --results leaderboards/records --html
    leaderboards/site --clips-from RESULTS`, run from the repository's root. The clips come
    from the runs' checkpoints, which are not committed: every other byte is rebuilt here,
    and every clip a page shows is in the site."""
    monkeypatch.chdir(ROOT)
    build_site(Path("leaderboards/records"), tmp_path / "site", Path("leaderboards"))
    made = {p.relative_to(tmp_path / "site"): p for p in (tmp_path / "site").rglob("*")}
    committed = {p.relative_to(SITE): p for p in SITE.rglob("*")}
    clips = {name for name in committed if name.parts[0] == "clips"}
    assert sorted(made) == sorted(set(committed) - clips)
    for name, path in made.items():
        if path.is_dir():
            continue
        if name.parts[0] == "boards" and name.suffix == ".html":
            shown = set(re.findall(r'src="\.\./(clips/[^"]+)"', committed[name].read_text()))
            assert {Path(c) for c in shown} <= clips, name
            assert path.read_text() == _without_clips(committed[name].read_text()), name
        else:
            assert path.read_bytes() == committed[name].read_bytes(), name


def test_every_committed_record_names_a_clean_commit():
    """Anyone must be able to re-run a record on the board: no `+dirty` tree anywhere under
    leaderboards/ (the retracted board's records live only in the history)."""
    records = sorted(BOARD.rglob("*.json"))
    assert records
    dirty = [p.name for p in records if "+dirty" in p.read_text()]
    assert not dirty, f"records from uncommitted trees: {dirty[:3]}"


@pytest.mark.slow
def test_committed_records_pass_publishing_on_this_code(tmp_path, monkeypatch):
    """Each standard dataset is regenerated by this code and publishing checks every record
    (seal, names, clean commit, dataset hash), so a change that makes the board stale fails."""
    monkeypatch.setenv("SYMBENCH_HOME", str(tmp_path / "home"))
    from symbench.core.config.presets import parse_dataset_id
    from symbench.core.data.generation.generate import ensure_dataset

    records = load_records(BOARD / "records")
    assert records, "the live board has no records"
    for dataset in sorted({r.dataset.id for _, r in records}):
        parsed = parse_dataset_id(dataset)
        assert parsed is not None, f"{dataset} is not a standard dataset id"
        ensure_dataset(*parsed, workers=min(2, os.cpu_count() or 1), show_progress=False)
    written = publish([p for p, _ in records], tmp_path / "board")
    assert len(written) >= len(records)
    for path in (tmp_path / "board").iterdir():
        if path.suffix in MADE:
            assert path.read_bytes() == (BOARD / path.name).read_bytes(), path.name

"""The site keeps matched sizes apart: their own section per protocol, after the default
sizes, with their own entry pages; default-size names stay as they were."""

from __future__ import annotations

from pathlib import Path

from symbench.core.board.site import build_site
from symbench.core.runs.results import write_record


def test_matched_sections_and_entries_are_their_own(tmp_path: Path, make_record):
    results = tmp_path / "results"
    results.mkdir()
    for seed in range(3):
        for model, rmse in (("sdnn", 0.1), ("ffnn", 0.5)):
            default = write_record(make_record(model=model, seed=seed, rmse=rmse), tmp_path / "d")
            write_record(default, results / f"{default.key()}.json")
            record = make_record(model=model, seed=seed, rmse=1 - rmse)
            record["model"] |= {"matched_parameters": 100000, "parameters": 106000}
            sized = write_record(record, tmp_path / "m")
            write_record(sized, results / f"{sized.key()}.json")
    out = tmp_path / "site"
    build_site(results, out, tmp_path / "board")
    page = next((out / "boards").glob("*.html")).read_text()
    assert page.index("<h2>paper protocol</h2>") < page.index(
        "<h2>paper protocol, matched at 100 000 parameters</h2>"
    )
    assert "+6.0 % (outside 5 %)" in page
    entries = sorted(p.name for p in (out / "entries").glob("*.html"))
    assert len(entries) == 4
    assert sum("matched-100000" in name for name in entries) == 2
    index = (out / "index.html").read_text()
    assert index.index("paper protocol:") < index.index("paper protocol, matched at 100 000")

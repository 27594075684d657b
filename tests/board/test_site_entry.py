"""An entry page's layout: the seeds' summary first (a row per seed with the record's
numbers, then their mean and 95 % interval), every raw value folded in a closed <details>,
no long JSON outside one; and the readable forms it writes numbers and metrics in. The
page is read with the standard library's HTML parser; tests/board/test_site_browser.py
checks the same page in a browser (its width on a phone, its height)."""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from html.parser import HTMLParser
from pathlib import Path

from site_records import HEXA, LEGACY_MODEL, SEEDS, runs_of

from symbench.core.board.cells import count, number
from symbench.core.board.site.metrics import evaluator_metrics
from symbench.core.board.site.provenance import provenance
from symbench.core.board.site.seeds import seed_summary
from symbench.core.runs.results import read_record, write_record

FFNN_IID = f"entries/{HEXA}__converge__iid__ffnn__acc__torch.html"
LEGACY = f"entries/{HEXA}__paper__iid__{LEGACY_MODEL}__acc__torch.html"
LONGEST_JSON = 80  # characters of JSON that may stand outside <details>


@dataclass
class Table:
    css: str
    folded: bool  # inside a <details>
    rows: list[list[str]] = field(default_factory=list)  # the text of each cell, by row


@dataclass
class Entry:
    tables: list[Table] = field(default_factory=list)  # in the page's order
    unfolded: list[str] = field(default_factory=list)  # text outside any <details>
    raw: list[tuple[bool, str]] = field(default_factory=list)  # pre.raw: (folded, text)
    details: list[bool] = field(default_factory=list)  # each <details>: open?


class _Reader(HTMLParser):
    def __init__(self) -> None:
        super().__init__(convert_charrefs=True)
        self.entry = Entry()
        self.depth = 0  # of <details>
        self.tables: list[Table] = []
        self.pre: list[str] | None = None

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        a = dict(attrs)
        if tag == "details":
            self.depth += 1
            self.entry.details.append("open" in a)
        elif tag == "table":
            self.tables.append(Table(a.get("class") or "", self.depth > 0))
            self.entry.tables.append(self.tables[-1])
        elif tag == "tr" and self.tables:
            self.tables[-1].rows.append([])
        elif tag in ("td", "th") and self.tables:
            self.tables[-1].rows[-1].append("")
        elif tag == "pre" and a.get("class") == "raw":
            self.pre = []

    def handle_endtag(self, tag: str) -> None:
        if tag == "details":
            self.depth -= 1
        elif tag == "table":
            self.tables.pop()
        elif tag == "pre" and self.pre is not None:
            self.entry.raw.append((self.depth > 0, "".join(self.pre)))
            self.pre = None

    def handle_data(self, data: str) -> None:
        if self.pre is not None:
            self.pre.append(data)
        if self.depth == 0:
            self.entry.unfolded.append(data)
        if self.tables and self.tables[-1].rows and self.tables[-1].rows[-1]:
            row = self.tables[-1].rows[-1]
            row[-1] = " ".join(f"{row[-1]} {data}".split())


def read_entry(path: Path) -> Entry:
    reader = _Reader()
    reader.feed(path.read_text())
    reader.close()
    return reader.entry


def json_values(text: str) -> list[str]:
    """Every JSON object or array that `text` holds, as written there."""
    decoder, found, start = json.JSONDecoder(), [], 0
    while (starts := [i for i in (text.find("{", start), text.find("[", start)) if i >= 0]) != []:
        i = min(starts)
        try:
            _, end = decoder.raw_decode(text, i)
        except json.JSONDecodeError:
            start = i + 1
            continue
        found.append(text[i:end])
        start = end
    return found


def test_the_seeds_summary_comes_first_with_each_seeds_numbers_and_their_interval(site):
    entry = read_entry(site / FFNN_IID)
    summary = entry.tables[0]
    assert summary.css == "seeds" and not summary.folded
    header, *seeds, mean = summary.rows
    assert header == [
        "seed",
        "test RMSE (N·m)",
        "closed-loop score",
        "steps",
        "stop reason",
        "verification",
    ]
    assert seeds == [
        [str(s), f"0.40{s}", f"0.{20 + 5 * s}0", f"{20 + 10 * s}", "2 checks", verdict]
        for s, verdict in zip(SEEDS, ["sealed, not on the board"] * len(SEEDS))
    ]
    # the 95 % bootstrap interval of 3 seeds is the range of their values
    assert mean == ["mean [95 % interval]", "0.401 [0.400, 0.402]", "0.250 [0.200, 0.300]"] + [
        "30.0 [20.0, 40.0]",
        "",
        "",
    ]


def test_a_schema_1_rows_summary_says_what_it_lacks(site):
    header, *seeds, mean = read_entry(site / LEGACY).tables[0].rows
    assert "steps" not in header and "closed-loop score" not in header  # no seed has them
    assert [row[-2:] for row in seeds] == [["not recorded (schema 1)", "not verified"]] * 3
    assert mean[1] == "0.310 [0.300, 0.320]"


def test_raw_values_are_folded_in_closed_details(site, results):
    entry = read_entry(site / FFNN_IID)
    assert entry.details and not any(entry.details)  # closed until a reader opens one
    assert {t.css for t in entry.tables if t.folded} == {"provenance", "metrics"}
    assert {t.css for t in entry.tables if not t.folded} == {"seeds", "board"}
    runs = runs_of(results, HEXA, "converge", "iid", "ffnn")
    assert all(folded for folded, _ in entry.raw)
    assert [json.loads(text) for _, text in entry.raw] == [
        metrics for run in runs for metrics in run["metrics"].values()
    ]  # every evaluator's metrics at full precision


def test_no_long_json_stands_outside_details(site, results):
    for page in (FFNN_IID, LEGACY):
        unfolded = read_entry(site / page).unfolded
        assert max(map(len, json_values(" ".join(unfolded))), default=0) <= LONGEST_JSON
    assert json_values('a [1, 2] b {"c": [3]} [not json') == ["[1, 2]", '{"c": [3]}']


def test_numbers_are_written_as_the_boards_write_a_mean():
    n = "\u202f"  # the narrow no-break space that groups thousands
    assert [number(x) for x in (0.0996, 0.09996, 12345.6, 999.7, 2.0, 0.0, 7, 0.00123)] == [
        "0.0996",
        "0.1000",  # the digits of 0.09996's magnitude, as the boards write a mean
        f"12{n}346",
        f"1{n}000",
        "2.00",
        "0",
        "7",
        "0.00123",
    ]
    # below 0.001 fixed notation would be a row of zeros
    assert number(0.000123) == "1.23 \N{MULTIPLICATION SIGN} 10⁻⁴"
    assert number(1.880926556647434e-15) == "1.88 \N{MULTIPLICATION SIGN} 10⁻¹⁵"
    assert number(-4.5e-7) == "-4.50 \N{MULTIPLICATION SIGN} 10⁻⁷"
    assert (count(1, "seed"), count(3, "seed"), count(2, "entry", "entries")) == (
        "1 seed",
        "3 seeds",
        "2 entries",
    )


def test_per_reference_lists_are_summarised_and_short_ones_shown_whole():
    closed_loop = {
        "references": 5,
        "pd_gains": [2.0, 0.30000000000000004],
        "failures": ["fell", "fell", "foot lost"],
        "judged": {"seed": 0, "checkpoint": "ab" * 32},
        "by_pd_fraction": {"0.1": {"model": {}, "tracking_score": 0.5}},
        "per_reference": [
            {"scenario": "a", "open_loop_torque_rmse": 0.1, "tracking_score": None},
            {"scenario": "b", "open_loop_torque_rmse": 0.3, "tracking_score": 0.25},
            {"scenario": "c", "open_loop_torque_rmse": 0.2, "tracking_score": 0.75},
            {"scenario": "d", "open_loop_torque_rmse": 0.4, "tracking_score": 1.0},
            {"scenario": "e", "open_loop_torque_rmse": 0.0, "tracking_score": 0.0},
        ],
        "costs": [0.5, 0.25, 0.75, 1.0, 0.0],
    }
    (shown,) = evaluator_metrics({"closed-loop": closed_loop})
    assert shown.title == "7 metrics of closed-loop"
    assert dict(shown.rows) == {
        "references": "5",
        "pd_gains": "[2.00, 0.300]",
        "failures": "3 values, 2 distinct",
        "judged · seed": "0",
        "judged · checkpoint": "ab" * 32,
        "by_pd_fraction · 0.1": "2 fields: model, tracking_score",
        "per_reference": "5 entries",
        "per_reference · open_loop_torque_rmse": "5 values: mean 0.200, min 0, max 0.400",
        "per_reference · tracking_score": "4 values (1 none): mean 0.500, min 0, max 1.00",
        "costs": "5 values: mean 0.500, min 0, max 1.00",
    }
    assert json.loads(shown.raw) == closed_loop


def test_the_summary_shows_training_time_where_records_have_it(make_record, tmp_path):
    runs = []
    for seed, seconds in zip(SEEDS, (10.0, 20.0, 60.0)):
        record = make_record(seed=seed)
        record["timings_s"] = {"training_s": seconds}
        path = tmp_path / f"seed{seed}.json"
        write_record(record, path)
        read = read_record(path)
        runs.append((read, provenance(path, read, tmp_path / "board")))
    summary = seed_summary(runs)
    time = [c.header for c in summary.columns].index("wall time training (s)")
    assert [row.cells[time] for row in summary.rows] == ["10.0", "20.0", "60.0"]
    assert summary.mean[time] == ("30.0", "[10.0, 60.0]")
    assert summary.over == "3 seeds"
    assert seed_summary(runs[:1]).mean[0] == ("0.100", "")  # one seed: no interval

"""`symbench tune` goes on past the grid's edge where the best rate sits on it, one rate at a
time at the best width, at most MAX_EXTENSIONS rates, resumably; and `symbench tune
summarize` turns the summaries into the board's table and tuned_rates.toml's lines.

Training is a stand-in whose validation loss is known: smallest at a chosen rate (in log
distance) and at width scale 0.5, so every search here takes a fraction of a second."""

from __future__ import annotations

import json
import math
import tomllib
from pathlib import Path
from types import SimpleNamespace

import pytest
from cli_invoke import error_line, invoke

from symbench.core.plugin import registry
from symbench.core.runs import tune as tuning
from symbench.core.runs import tune_summary
from symbench.core.runs.spec import RunSpec
from symbench.core.training import loop
from symbench.plugins import zoo

RATES, SCALES = (1e-3, 3e-3), (0.5, 1.0)
MODELS = ("ffnn", "ffnn-leg", "gnn", "sdgnn", "sdnn")
BOARD_TUNING = Path(__file__).resolve().parents[2] / "leaderboards" / "tuning"


def spec(tmp_path, model="ffnn") -> RunSpec:
    return RunSpec(model=model, robot="hexa", preset="smoke", evaluators=(), output=tmp_path)


def stand_in(
    monkeypatch, optimum: float, crash_at: int | None = None, best_scale: float = 0.5
) -> list[tuple]:
    """Replaces training by a loss of log distance to `optimum` (plus 0.1 away from width
    scale `best_scale`); returns the list of (rate, width scale) trained, in order.
    `crash_at`: the training that is interrupted, as by Ctrl-C."""
    trained: list[tuple] = []

    def train(entry, train_set, val_set, config, checkpoint_dir=None):
        if len(trained) == crash_at:
            raise KeyboardInterrupt
        scale = config.hyper["width"] / 256
        trained.append((config.learning_rate, scale))
        loss = math.log(config.learning_rate / optimum) ** 2 + (0.0 if scale == best_scale else 0.1)
        return SimpleNamespace(
            n_params=config.hyper["width"], history={"val_loss": [loss]}, steps=1, stopped_by="x"
        )

    monkeypatch.setattr(loop, "train", train)
    return trained


def search(tmp_path, model="ffnn", rates=RATES, **kwargs) -> dict:
    return tuning.tune(spec(tmp_path, model), rates, SCALES, tmp_path, lambda _: None, **kwargs)


def test_a_best_on_the_low_edge_extends_downward_until_it_is_interior(
    smoke_hexa, tmp_path, monkeypatch
):
    trained = stand_in(monkeypatch, optimum=2e-4)
    summary = search(tmp_path)
    # one grid step (x 1/3) at a time, at the best width: 3.33e-4 is best but on the edge,
    # then 1.11e-4 is worse, so 3.33e-4 is interior
    assert summary["extended_rates"] == [3.33e-4, 1.11e-4]
    assert trained[4:] == [(3.33e-4, 0.5), (1.11e-4, 0.5)]
    assert len(trained) == len(set(trained)) == 6
    assert summary["best"]["learning_rate"] == 3.33e-4 and summary["best_on_edge"] is False
    assert summary["complete"] and len(summary["trials"]) == 6
    assert summary["grid"] == [
        {"learning_rate": r, "width_scale": s} for r in RATES for s in SCALES
    ]
    assert json.loads(tuning.summary_path(tmp_path, spec(tmp_path)).read_text()) == summary


def test_at_most_three_rates_are_added_and_a_best_left_on_the_edge_is_said(
    smoke_hexa, tmp_path, monkeypatch
):
    trained = stand_in(monkeypatch, optimum=1e-7)
    summary = search(tmp_path)
    assert tuning.MAX_EXTENSIONS == 3
    assert summary["extended_rates"] == [3.33e-4, 1.11e-4, 3.7e-5]
    assert len(trained) == 4 + 3
    assert summary["best"]["learning_rate"] == 3.7e-5 and summary["best_on_edge"] is True


def test_a_best_on_the_high_edge_extends_upward_but_never_to_a_rate_of_one(
    smoke_hexa, tmp_path, monkeypatch
):
    stand_in(monkeypatch, optimum=0.95)
    summary = search(tmp_path, rates=(0.1, 0.3))
    assert summary["extended_rates"] == [0.9]  # the next, 2.7, is no learning rate
    assert summary["best"]["learning_rate"] == 0.9 and summary["best_on_edge"] is True


def test_a_single_rate_is_extended_by_the_default_step_both_ways(smoke_hexa, tmp_path, monkeypatch):
    stand_in(monkeypatch, optimum=1e-3)
    summary = search(tmp_path, rates=(1e-3,))
    # below first (3.33e-4: worse), so 1e-3 is on the high edge: above (3e-3: worse)
    assert summary["extended_rates"] == [3.33e-4, 3e-3]
    assert summary["best"]["learning_rate"] == 1e-3 and summary["best_on_edge"] is False


def test_an_interrupted_extension_resumes_without_retraining_finished_points(
    smoke_hexa, tmp_path, monkeypatch
):
    whole = stand_in(monkeypatch, optimum=2e-4)
    expected = search(tmp_path / "whole")
    first = stand_in(monkeypatch, optimum=2e-4, crash_at=5)  # during the second extension
    with pytest.raises(KeyboardInterrupt):
        search(tmp_path)
    partial = json.loads(tuning.summary_path(tmp_path, spec(tmp_path)).read_text())
    assert partial["extended_rates"] == [3.33e-4, 1.11e-4] and not partial["complete"]
    again = stand_in(monkeypatch, optimum=2e-4)
    summary = search(tmp_path)
    assert first == whole[:5] and again == whole[5:]  # the interrupted point only
    assert {k: v for k, v in summary.items() if k != "git_commit"} == {
        k: v for k, v in expected.items() if k != "git_commit"
    }


def test_the_command_can_leave_the_edges_alone_and_says_the_best_is_on_one(
    smoke_hexa, tmp_path, monkeypatch
):
    trained = stand_in(monkeypatch, optimum=2e-4)
    command = ("tune", "--model", "ffnn", "--robot", "hexa", "--preset", "smoke")
    rates = ("--learning-rates", "0.001,0.003", "--output", tmp_path)
    result = invoke(*command, *rates, "--no-extend-edges")
    assert result.exit_code == 0, result.output
    assert len(trained) == 6  # the grid: 2 rates x the default 3 widths
    assert "the best rate is on the edge of the rates tried" in result.stdout
    summary = json.loads(tuning.summary_path(tmp_path, spec(tmp_path)).read_text())
    assert summary["extended_rates"] == [] and summary["best_on_edge"] is True
    result = invoke(*command, *rates)  # the same search, now extended: the grid not again
    assert result.exit_code == 0, result.output
    assert len(trained) == 8 and "rates added past the grid's edge: 0.000333, 0.000111" in (
        result.stdout
    )


def test_summarize_makes_the_board_table_and_the_lines_of_tuned_rates(
    smoke_hexa, tmp_path, monkeypatch
):
    stand_in(monkeypatch, optimum=2e-4, best_scale=1.0)
    search(tmp_path, "ffnn")
    stand_in(monkeypatch, optimum=0.95)  # best at width scale 0.5: the rate chosen is 1's
    search(tmp_path, "ffnn-leg", rates=(0.1, 0.3))
    table = tmp_path / "board" / "summary.md"
    result = invoke("tune", "summarize", str(tmp_path), "--out", str(table))
    assert result.exit_code == 0, result.output
    rows = [line for line in table.read_text().splitlines() if line.startswith("| hexa")]
    assert rows[0].startswith(
        "| hexa | ffnn | torch | hexa-climb-smoke-v7 | iid | 0.000333 | 0.000111: 0.347; "
        "**0.000333: 0.26**; 0.001: 2.59; 0.003: 7.33 | no | 0.000333, 1 (width 256): 0.26 | "
        "yes | "
    )
    # extended at width scale 0.5, its best: at 1, the rate chosen is on the edge
    assert rows[1].startswith(
        "| hexa | ffnn-leg | torch | hexa-climb-smoke-v7 | iid | 0.3 | 0.1: 5.17; **0.3: 1.43** "
        "| yes | 0.9, 0.5 (width 128): 0.00292 | yes | "
    )
    assert table.read_text() in result.stdout
    lines = result.stdout[result.stdout.index("# the lines for") :]
    assert "[ffnn.torch]\nhexa = 0.000333\n" in lines
    assert "[ffnn-leg.torch]\nhexa = 0.3  # on the edge of the rates tried\n" in lines
    pasted = tmp_path / "tuned_rates.toml"
    pasted.write_text(lines)
    assert zoo.tuned_rates(pasted) == tomllib.loads(lines)
    assert tomllib.loads(lines)["ffnn"]["torch"] == {"hexa": 3.33e-4}


def test_summarize_refuses_what_is_no_summary_in_one_line(tmp_path):
    assert error_line(invoke("tune", "summarize", str(tmp_path)), 1) == (
        f"Error: {tmp_path} holds no `symbench tune` summary (*.tune.json)"
    )
    (tmp_path / "a.tune.json").write_text(json.dumps({"robot": "hexa"}))
    assert error_line(invoke("tune", "summarize", str(tmp_path)), 1) == (
        f"Error: tuning summary {tmp_path / 'a.tune.json'} has no 'model': not a `symbench "
        "tune` summary"
    )
    assert "takes no search options (--model)" in error_line(
        invoke("tune", "--model", "ffnn", "summarize", str(tmp_path)), 2
    )
    assert "Missing option '--model'" in error_line(invoke("tune", "--robot", "hexa"), 2)


def write_summary(path: Path, robot) -> None:
    """A summary of one finished trial, of `robot`."""
    trial = {"learning_rate": 1e-3, "width_scale": 1.0, "hyper": {"width": 256}}
    trial |= {"parameters": 1, "best_val_loss": 0.5, "steps": 1, "stopped_by": "x"}
    names = {"robot": robot, "model": "ffnn", "backend": "torch", "dataset": "d"}
    path.write_text(json.dumps({**names, "trials": [trial], "best": trial}))


def test_summarize_refuses_a_name_that_is_no_text_naming_the_file(tmp_path):
    """Before: "internal error: TypeError: '<' not supported between instances of 'NoneType'
    and 'str'" (the summaries are sorted by robot); found by the property suite."""
    write_summary(tmp_path / "a.tune.json", None)
    write_summary(tmp_path / "b.tune.json", "hexa")
    assert error_line(invoke("tune", "summarize", str(tmp_path)), 1) == (
        f"Error: tuning summary {tmp_path / 'a.tune.json'} has robot null, not a name: not a "
        "`symbench tune` summary"
    )


def test_summarize_refuses_an_out_it_cannot_write_before_reading(tmp_path):
    """Before: --out under a file ended in "internal error: FileExistsError" once the
    summaries were read."""
    write_summary(tmp_path / "a.tune.json", "hexa")
    (tmp_path / "blocker").write_text("a file")
    under_a_file = tmp_path / "blocker" / "t.md"
    assert error_line(invoke("tune", "summarize", tmp_path, "--out", under_a_file), 2) == (
        f"Error: Invalid value for '--out': '{under_a_file}': cannot write there (File exists)"
    )
    assert error_line(invoke("tune", "summarize", tmp_path, "--out", tmp_path), 2) == (
        f"Error: Invalid value for '--out': '{tmp_path}' is a folder, not a file"
    )


def test_the_board_s_hexa_searches_give_the_zoo_s_learning_rates():
    """The searches of leaderboards/tuning (several files per model: they were extended past
    the edge by hand) choose the rates the zoo has: the tool reproduces the hand's work."""
    summaries = tune_summary.read_summaries(BOARD_TUNING)
    lines = tomllib.loads(tune_summary.toml_lines(summaries))
    assert {model: rates["torch"]["hexa"] for model, rates in lines.items()} == {
        name: registry.model(name, "torch").learning_rate for name in MODELS
    }

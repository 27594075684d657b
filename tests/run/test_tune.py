"""`symbench tune`: learning rate x width on validation data only, resumable, for any model."""

from __future__ import annotations

import dataclasses
import json
from unittest import mock

import pytest
from cli_invoke import error_line, invoke

from symbench.core.common.errors import SymbenchError
from symbench.core.data import load_dataset
from symbench.core.plugin import registry
from symbench.core.runs import tune as tuning
from symbench.core.runs.run_config import train_config
from symbench.core.runs.spec import RunSpec
from symbench.core.training import loop

RATES, SCALES = (1e-3, 3e-3), (0.5, 1.0)


def spec(tmp_path, model="ffnn") -> RunSpec:
    return RunSpec(model=model, robot="hexa", preset="smoke", evaluators=(), output=tmp_path)


def test_every_grid_point_is_trained_and_scored_by_its_validation_loss(smoke_hexa, tmp_path):
    run = spec(tmp_path)
    summary = tuning.tune(run, RATES, SCALES, tmp_path, report=lambda _: None, extend_edges=False)
    assert summary["complete"] and len(summary["trials"]) == 4
    widths = sorted({(t["width_scale"], t["hyper"]["width"]) for t in summary["trials"]})
    assert widths == [(0.5, 128), (1.0, 256)]  # ffnn's width 256, scaled
    assert len({t["parameters"] for t in summary["trials"]}) == 2
    best = min(summary["trials"], key=lambda t: t["best_val_loss"])
    assert summary["best"] == best
    # the score is the validation loss a plain training with those values reaches
    entry = registry.model("ffnn", "torch")
    dataset = load_dataset(smoke_hexa.dataset_id)
    train_set, val_set, _ = dataset.split_views(entry.view, entry.variant, "iid", 0)
    config = dataclasses.replace(
        train_config(run), learning_rate=best["learning_rate"], hyper=best["hyper"]
    )
    again = loop.train(entry, train_set, val_set, dataclasses.replace(config, progress=False))
    assert min(again.history["val_loss"]) == best["best_val_loss"]
    written = json.loads(tuning.summary_path(tmp_path, run).read_text())
    assert written["best"] == best and written["split"] == "iid"
    assert "test trajectories never used" in written["scored_by"]


def test_an_interrupted_search_resumes_without_retraining_finished_trials(
    smoke_hexa, tmp_path, monkeypatch
):
    run, trained = spec(tmp_path), []
    real_train = loop.train

    def crashing_train(*args, **kwargs):
        if len(trained) == 2:
            raise KeyboardInterrupt  # as if stopped during the third trial
        trained.append(args[3].learning_rate)
        return real_train(*args, **kwargs)

    monkeypatch.setattr(loop, "train", crashing_train)
    with pytest.raises(KeyboardInterrupt):
        tuning.tune(run, RATES, SCALES, tmp_path, report=lambda _: None, extend_edges=False)
    partial = json.loads(tuning.summary_path(tmp_path, run).read_text())
    assert len(partial["trials"]) == 2 and not partial["complete"]
    monkeypatch.setattr(
        loop, "train", lambda *a, **k: (trained.append(a[3]), real_train(*a, **k))[1]
    )
    summary = tuning.tune(run, RATES, SCALES, tmp_path, report=lambda _: None, extend_edges=False)
    assert summary["complete"] and len(summary["trials"]) == 4
    assert len(trained) == 4  # two before the crash, the two left after it


def test_a_larger_grid_in_the_same_folder_trains_only_its_new_points(
    smoke_hexa, tmp_path, monkeypatch
):
    run, trained = spec(tmp_path), []
    real_train = loop.train
    monkeypatch.setattr(
        loop, "train", lambda *a, **k: (trained.append(a[3].learning_rate), real_train(*a, **k))[1]
    )
    tuning.tune(run, RATES[:1], SCALES, tmp_path, report=lambda _: None, extend_edges=False)
    summary = tuning.tune(run, RATES, SCALES, tmp_path, report=lambda _: None, extend_edges=False)
    assert summary["complete"] and len(summary["trials"]) == 4
    assert trained == [RATES[0], RATES[0], RATES[1], RATES[1]]  # the first two not again


def test_a_model_without_widths_searches_the_learning_rate_only(smoke_hexa, tmp_path, monkeypatch):
    entry = registry.model("ffnn", "torch")
    monkeypatch.setattr(tuning, "model_entry", lambda _: dataclasses.replace(entry, widths=()))
    summary = tuning.tune(
        spec(tmp_path), RATES, SCALES, tmp_path, report=lambda _: None, extend_edges=False
    )
    assert [(t["learning_rate"], t["width_scale"], t["hyper"]) for t in summary["trials"]] == [
        (1e-3, 1.0, {}),
        (3e-3, 1.0, {}),
    ]


def test_the_command_prints_the_trials_and_refuses_bad_values_in_one_line(smoke_hexa, tmp_path):
    command = ("tune", "--model", "ffnn", "--robot", "hexa", "--preset", "smoke")
    result = invoke(
        *command, "--learning-rates", "0.001", "--width-scales", "1", "--output", tmp_path
    )
    assert result.exit_code == 0, result.output
    assert "(best)" in result.stdout and "width 256" in result.stdout
    assert "Invalid value for '--learning-rates'" in error_line(
        invoke(*command, "--learning-rates", "0", "--output", tmp_path), 2
    )
    assert error_line(invoke("tune", "--model", "fnn", "--robot", "hexa"), 1).startswith(
        "Error: unknown model 'fnn'"
    )


def test_a_damaged_journal_is_named_with_how_to_go_on(smoke_hexa, tmp_path):
    """Before: "internal error: JSONDecodeError: Expecting value: line 1 column 1 (char 0)",
    the journal unnamed and nothing said how to go on."""
    journal = tuning.journal_path(tmp_path, spec(tmp_path))
    journal.write_bytes(b"\n{}\n")  # a line that is no JSON, with another after it
    result = invoke(
        "tune", "--model", "ffnn", "--robot", "hexa", "--preset", "smoke", "--output", tmp_path
    )
    assert error_line(result, 1) == (
        f"Error: tuning journal {journal} is damaged (JSONDecodeError: Expecting value: line 2 "
        "column 1 (char 1)); to go on, move it aside and run the same command again: the "
        "search starts afresh (its finished trials are trained again)"
    )


def test_a_width_scale_that_cannot_build_the_model_is_refused_before_any_work(
    home, tmp_path, monkeypatch
):
    """Before: any scale up to 1000 was taken, and sdnn at 1000 x its widths (147 billion
    parameters) asked torch for 590 GB in the search's first trial."""
    monkeypatch.setattr(loop, "train", mock.Mock(side_effect=AssertionError("trained")))
    command = ("tune", "--model", "sdnn", "--robot", "hexa", "--preset", "smoke")
    result = invoke(*command, "--width-scales", "1,1000", "--output", tmp_path)
    assert error_line(result, 1) == (
        "Error: --width-scales 1000: a width scale of model sdnn/torch is in [0.001, 64]; the "
        "nearest allowed: 64"
    )
    assert not home.exists()  # refused before the dataset was made


def test_a_width_scale_a_plugin_cannot_build_names_the_nearest_that_builds(home, monkeypatch):
    """A build function may refuse widths (here an odd latent): the scale is refused before
    any work, naming the nearest scale whose network builds."""
    entry = registry.model("sdnn", "torch")

    def even_only(dims, latent=128, **sizes):
        if latent % 2:
            raise ValueError(f"latent must be even, got {latent}")
        return entry.build(dims, latent=latent, **sizes)

    odd = dataclasses.replace(entry, build=even_only)
    monkeypatch.setattr(tuning, "model_entry", lambda _: odd)
    monkeypatch.setattr(loop, "train", mock.Mock(side_effect=AssertionError("trained")))
    with pytest.raises(SymbenchError) as error:
        tuning.tune(spec(home), RATES, (1.0, 0.5078125), home, report=lambda _: None)
    assert str(error.value) == (
        "--width-scales 0.507812 (latent=65): model sdnn/torch could not be built: ValueError: "
        "latent must be even, got 65; nearest buildable: 0.5 (latent=64)"
    )
    assert not home.exists()

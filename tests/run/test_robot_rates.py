"""A model's learning rate per robot (`ModelEntry.learning_rates`, the built-ins' from
symbench/plugins/tuned_rates.toml): a run on that robot (or its asymmetric variant) trains
with it, any other robot with the model's own; the record says the rate used, and a changed
rate makes a record of the old one another configuration, never silently reused.

The runs are smoke runs of ffnn (20 steps) on the stand-in's hexa data: seconds."""

from __future__ import annotations

import dataclasses

import pytest

from symbench.core.common.errors import SymbenchError
from symbench.core.plugin import registry
from symbench.core.runs.identity import record_state
from symbench.core.runs.results import read_record
from symbench.core.runs.run_config import configuration, train_config
from symbench.core.runs.runner import RunSpec, run
from symbench.core.runs.verify import replay_spec
from symbench.plugins import zoo

OWN = 3e-3  # ffnn's own rate (zoo.py), chosen on hexa


def tuned(monkeypatch, tmp_path, text: str) -> None:
    """The built-in models' per-robot rates read from `text` instead of tuned_rates.toml."""
    path = tmp_path / "tuned_rates.toml"
    path.write_text(text)
    monkeypatch.setattr(zoo, "TUNED_RATES", path)


def spec(tmp_path, robot: str = "hexa", **changes) -> RunSpec:
    return RunSpec(
        model="ffnn",
        robot=robot,
        preset="smoke",
        evaluators=("torque-error",),
        output=tmp_path / "results",
        progress=False,
        max_steps=20,
        **changes,
    )


def test_a_robot_s_tuned_rate_is_its_runs_and_only_its(tmp_path, monkeypatch):
    tuned(monkeypatch, tmp_path, "[ffnn.torch]\nhexa = 0.002\n")
    entry = registry.model("ffnn", "torch")
    assert entry.learning_rates == {"hexa": 2e-3} and entry.learning_rate == OWN
    assert registry.model("ffnn", "jax").learning_rates == {}  # another backend's table
    assert registry.model("sdnn", "torch").learning_rates == {}
    rates = {
        robot: (train_config(spec(tmp_path, robot)).learning_rate, rate_of(tmp_path, robot))
        for robot in ("hexa", "hexa-asym-0.05", "magneto")
    }
    # the tuned rate named in the configuration; the model's own left unnamed (None), as in
    # every configuration (and resume checkpoint) made before per-robot rates
    assert rates == {"hexa": (2e-3, 2e-3), "hexa-asym-0.05": (2e-3, 2e-3), "magneto": (None, OWN)}


def rate_of(tmp_path, robot: str) -> float:
    return configuration(spec(tmp_path, robot))["training learning_rate"]


def test_a_wrong_table_of_rates_is_refused_naming_it(tmp_path):
    path = tmp_path / "tuned_rates.toml"
    for text, message in (
        ("[fnn.torch]\nhexa = 0.002\n", "tuned_rates.toml: no built-in model 'fnn'"),
        ("[ffnn.tf]\nhexa = 0.002\n", "tuned_rates.toml: model 'ffnn' has no backend 'tf'"),
        ("ffnn = 3\n", "tuned_rates.toml: 'ffnn' is not a table of backends"),
        ("[ffnn.torch\n", "tuned_rates.toml: not valid TOML"),
    ):
        path.write_text(text)
        with pytest.raises(SymbenchError) as error:
            zoo.tuned_rates(path)
        assert str(error.value).startswith(message)


def test_the_shipped_table_is_read_and_names_only_built_in_models():
    tables = zoo.tuned_rates(zoo.TUNED_RATES)
    assert set(tables) <= {a.name for a in zoo.ARCHITECTURES}


def test_a_changed_tuned_rate_makes_the_old_record_another_configuration(
    smoke_hexa, tmp_path, monkeypatch
):
    tuned(monkeypatch, tmp_path, "")  # hexa untuned: ffnn's own rate
    first = spec(tmp_path)
    run(first)
    assert read_record(first.record_path).model.learning_rate == OWN
    tuned(monkeypatch, tmp_path, "[ffnn.torch]\nhexa = 0.002\n")
    assert record_state(first) == (
        "different",
        "training learning_rate 0.003 in the record, 0.002 in this run",
    )
    with pytest.raises(SymbenchError, match="is a record of another configuration"):
        run(first)  # refused, not reused
    # nor is its resume checkpoint resumed with the new rate: its identity differs
    with pytest.raises(SymbenchError, match="holds a training of another model, data or conf"):
        run(dataclasses.replace(first, overwrite=True))
    fresh = dataclasses.replace(first, output=tmp_path / "fresh")
    run(fresh)
    record = read_record(fresh.record_path)
    assert record.model.learning_rate == record.training.config.learning_rate == 2e-3
    # `verify` replays the rate the record used, whatever the table says now
    tuned(monkeypatch, tmp_path, "[ffnn.torch]\nhexa = 0.001\n")
    replayed = replay_spec(record, tmp_path / "verify", workers=1)
    assert train_config(replayed).learning_rate == 2e-3

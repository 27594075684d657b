"""Evaluators declare what they need; a dataset that lacks it gets the evaluator skipped with a
one-line reason, shown in the run's table and kept in the record, never a failed run."""

from __future__ import annotations

import json
from types import SimpleNamespace

import pytest
from cli_invoke import invoke

import symbench
from symbench.core.config.presets import RECORD_PERIOD
from symbench.core.data.importing.importer import export_dataset, import_logs
from symbench.core.plugin import registry
from symbench.core.runs.evaluation import skip_reason, unmet_need
from symbench.core.runs.results import read_record

COMPLETE = {
    "robot": "hexa",
    "inclination_deg": 90.0,
    "heading_deg": 0.0,
    "yaw_deg": 0.0,
    "direction": "forward",
    "leg_order": None,
    "seed": 0,
    "seconds": 1.0,
}


def _dataset(source="imported", period=RECORD_PERIOD, unknown=(), **scenario):
    """A stand-in with what `unmet_need` reads: id, metadata, scenarios, spec."""
    metadata = {"source": source, "record_period_s": period, "unknown_columns": list(unknown)}
    return SimpleNamespace(
        id="logs", metadata=metadata, scenarios=({**COMPLETE, **scenario},), spec=object()
    )


def test_every_builtin_evaluator_declares_known_needs():
    needs = {name: entry.needs for name, entry in registry.collect("evaluators").items()}
    assert needs["closed-loop"] == ("simulator", "variant:next")
    assert needs["torque-error"] == ()
    for name, declared in needs.items():
        assert set(declared) <= set(symbench.EVALUATOR_NEEDS), name


def test_a_generated_dataset_provides_everything():
    generated = _dataset("generated", yaw_deg=None)  # whatever it holds
    assert [unmet_need(n, generated) for n in symbench.EVALUATOR_NEEDS] == [None] * 5


@pytest.mark.parametrize(
    ("dataset", "need", "reason"),
    [
        (
            _dataset(yaw_deg=None, seed=None),
            "simulator",
            "needs a simulator replay: dataset 'logs' is imported and its scenarios lack "
            "yaw_deg, seed",
        ),
        (
            _dataset(direction=None),
            "scenarios",
            "needs complete scenarios: dataset 'logs' is imported and its scenarios lack direction",
        ),
        (
            _dataset(period=0.001),
            "variant:next",
            "needs the next variant at the 6 ms record period: dataset 'logs' is recorded "
            "every 1 ms, so its next state is not the one 6 ms ahead",
        ),
        (
            _dataset(unknown=("contact",)),
            "contact",
            "needs known contact flags: dataset 'logs' declares contact unknown",
        ),
    ],
)
def test_an_unmet_need_gives_a_one_line_reason(dataset, need, reason):
    entry = symbench.EvaluatorEntry("e", evaluate=len, needs=("raw", need))
    assert skip_reason(entry, dataset) == reason
    assert unmet_need("raw", dataset) is None


def test_an_imported_dataset_with_complete_scenarios_can_be_replayed():
    assert unmet_need("simulator", _dataset(leg_order=None)) is None  # default leg order


@pytest.mark.slow  # the generalization evaluator trains on two more splits
def test_a_run_on_logs_without_yaws_skips_what_it_cannot_do(smoke_hexa, home, tmp_path):
    """closed-loop is skipped (no yaw to replay), generalization trains on the splits the
    logs allow and names the one they do not; the run succeeds and the record keeps both."""
    from symbench.core.data import load_dataset

    folder = export_dataset(load_dataset(smoke_hexa.dataset_id), tmp_path / "logs")
    manifest = json.loads((folder / "import.json").read_text())
    for entry in manifest["trajectories"]:
        del entry["scenario"]["yaw_deg"]
    (folder / "import.json").write_text(json.dumps(manifest))
    import_logs(folder, "hexa-logs")

    evaluators = "torque-error,closed-loop,generalization"
    result = invoke(
        *("run", "--model", "ffnn", "--dataset", "hexa-logs", "--preset", "smoke"),
        *("--evaluators", evaluators, "--max-steps", "10", "--output", tmp_path / "out"),
    )
    assert result.exit_code == 0, result.output
    rows = [" ".join(line.strip("│ ").split()) for line in result.stdout.splitlines()]
    assert "closed-loop │ skipped │ needs a simulator replay:" in rows
    assert "generalization │ skipped split │ dataset hexa-logs: some" in rows
    (path,) = (tmp_path / "out").glob("*.json")
    metrics = read_record(path).metrics
    assert metrics["closed-loop"] == {
        "skipped": "needs a simulator replay: dataset 'hexa-logs' is imported and its "
        "scenarios lack yaw_deg"
    }
    general = metrics["generalization"]
    assert general["splits"] == ["iid", "unseen-heading"]
    assert list(general["skipped_splits"]) == ["unseen-rotation"]
    assert "yaw_deg" in general["skipped_splits"]["unseen-rotation"]
    assert general["rmse_iid"] > 0 and "rmse_unseen-rotation" not in general
    assert metrics["torque-error"]["rmse"] > 0

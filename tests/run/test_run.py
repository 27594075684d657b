"""`symbench run` on the smoke preset: every built-in model on every robot writes a valid record."""

from __future__ import annotations

import pytest
from click.testing import CliRunner

from symbench.core.cli import build_cli
from symbench.core.errors import SymbenchError, UnknownNameError
from symbench.core.results import read_record
from symbench.core.runner import RunSpec, run

MODELS = ("sdnn", "sdgnn", "ffnn", "ffnn-leg", "gnn")
ROBOTS = ("magneto", "hexa", "nona")
EVALUATORS = ("torque-error", "equivariance", "invariance")


@pytest.mark.parametrize("robot", ROBOTS)
@pytest.mark.parametrize("model", MODELS)
def test_every_model_on_every_robot_writes_a_valid_record(smoke_home, tmp_path, model, robot):
    spec = RunSpec(model=model, robot=robot, preset="smoke", evaluators=EVALUATORS,
                   output=tmp_path, progress=False, max_epochs=2)
    record = run(spec)
    assert read_record(spec.record_path) == record
    assert record.dataset.id == f"{robot}-climb-smoke-v3"
    assert record.samples.train > 0 and record.samples.test > 0
    assert record.model.parameters > 0
    metrics = record.metrics
    assert metrics["torque-error"]["rmse"] > 0
    equivariance = metrics["equivariance"]["max_rel_error"]
    invariance = metrics["invariance"]["max_rel_change"]
    if record.model.equivariant:  # sdnn, sdgnn: exact up to float32
        assert equivariance < 1e-4
    else:  # measured honestly: an unconstrained network is visibly not equivariant
        assert equivariance > 1e-3
    if record.model.view == "leg_grouped":  # leg-frame and joint quantities only
        assert invariance < 1e-4
    else:  # vector and body_graph carry the world-frame base state: not invariant, honestly
        assert invariance > 1e-3


def test_cli_prints_a_table_and_writes_the_record(smoke_home, tmp_path):
    result = CliRunner().invoke(build_cli(), [
        "run", "--model", "sdnn", "--robot", "hexa", "--preset", "smoke", "--max-epochs", "2",
        "--evaluators", "torque-error", "--output", str(tmp_path)], catch_exceptions=False)
    assert result.exit_code == 0, result.output
    assert "torque-error" in result.stdout and "rmse" in result.stdout
    assert read_record(tmp_path / "hexa__iid__sdnn__acc__torch__seed0.json").split == "iid"


def test_names_are_checked_before_any_work(tmp_path):
    with pytest.raises(UnknownNameError, match="did you mean sdnn"):
        run(RunSpec(model="sdn", robot="hexa", output=tmp_path))
    with pytest.raises(UnknownNameError, match="did you mean torque-error"):
        run(RunSpec(model="sdnn", robot="hexa", evaluators=("torque-eror",), output=tmp_path))
    with pytest.raises(SymbenchError, match="preset"):
        run(RunSpec(model="sdnn", robot="hexa", preset="huge", evaluators=("torque-error",),
                    output=tmp_path))
    assert not list(tmp_path.iterdir())


def test_a_run_may_choose_the_next_variant(smoke_home, tmp_path):
    spec = RunSpec(model="sdnn", robot="hexa", preset="smoke", variant="next",
                   evaluators=("torque-error", "equivariance"), output=tmp_path,
                   progress=False, max_epochs=2)
    record = run(spec)
    assert record.model.variant == "next"
    assert spec.record_path.name == "hexa__iid__sdnn__next__torch__seed0.json"
    assert record.metrics["equivariance"]["max_rel_error"] < 1e-4
    with pytest.raises(UnknownNameError, match="did you mean next"):
        run(RunSpec(model="sdnn", robot="hexa", variant="nxt", output=tmp_path))


def test_timings_count_each_second_once(smoke_home, tmp_path):
    record = run(RunSpec(model="sdnn", robot="hexa", preset="smoke",
                         evaluators=("torque-error", "generalization"), output=tmp_path,
                         progress=False, max_epochs=2))
    timings = record.timings_s
    assert timings["retraining_s"] > 0 and timings["evaluation_s"] >= 0
    assert record.training.stopped_early == (record.training.epochs < 2)

"""`symbench run` gives a first result after one training; `--full` is the board's evaluation."""

from __future__ import annotations

from click.testing import CliRunner

from symbench.core.cli import build_cli
from symbench.core.runs import spec
from symbench.core.runs.results import read_record

SMOKE_RUN = ["run", "--model", "sdnn", "--robot", "hexa", "--preset", "smoke"]


def _run(tmp_path, monkeypatch, *extra: str):
    """The command's run spec as the runner receives it (nothing is trained)."""
    seen = []

    def stop(spec, on_stage):
        seen.append(spec)
        raise SystemExit(0)

    monkeypatch.setattr("symbench.core.runs.cli.run.run_spec", stop)
    result = CliRunner().invoke(build_cli(), [*SMOKE_RUN, "--output", str(tmp_path), *extra])
    return result, seen


def test_the_default_needs_one_training_and_full_is_the_boards_evaluation(tmp_path, monkeypatch):
    _, default = _run(tmp_path, monkeypatch)
    _, full = _run(tmp_path, monkeypatch, "--full")
    assert default[0].evaluators == spec.FIRST_RESULT_EVALUATORS
    assert full[0].evaluators == spec.DEFAULT_EVALUATORS
    assert not set(spec.FIRST_RESULT_EVALUATORS) & {"generalization", "closed-loop"}


def test_full_and_evaluators_together_are_a_usage_error(tmp_path):
    args = [*SMOKE_RUN, "--full", "--evaluators", "torque-error", "--output", str(tmp_path)]
    result = CliRunner().invoke(build_cli(), args)
    assert result.exit_code == 2
    assert result.stderr.splitlines()[-1] == (
        "Error: --full and --evaluators choose the evaluators twice; use one"
    )


def test_each_stage_is_announced_with_the_time_so_far(smoke_home, tmp_path):
    args = [*SMOKE_RUN, "--max-steps", "10", "--output", str(tmp_path)]
    result = CliRunner().invoke(build_cli(), args, catch_exceptions=False)
    assert result.exit_code == 0, result.output
    stages = [line for line in result.stdout.splitlines() if line.endswith("s so far)")]
    names = [line.rsplit(" (", 1)[0] for line in stages]
    assert names == [
        "dataset",
        "training",
        "evaluating torque-error",
        "evaluating equivariance",
        "evaluating invariance",
        "evaluating image-overlap",
    ]
    record = read_record(
        tmp_path / "hexa-climb-smoke-v7__smoke__iid__sdnn__acc__torch__converge__seed0.json"
    )
    assert list(record.metrics) == list(spec.FIRST_RESULT_EVALUATORS)

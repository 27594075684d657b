"""`--size NAME=INT` on run and sweep: a build keyword set by name, kept in the record (and
replayed by `symbench verify`); a keyword the model lacks is refused before any work."""

from __future__ import annotations

from cli_invoke import error_line, invoke

from symbench.core.runs.results import read_record


def test_run_records_the_size_it_was_given(smoke_hexa, tmp_path):
    out = tmp_path / "ring"
    common = ("--model", "sdnn", "--robot", "hexa", "--preset", "smoke", "--output", out)
    result = invoke("run", *common, "--size", "ring=1", "--evaluators", "torque-error")
    assert result.exit_code == 0, result.output
    (path,) = out.glob("*.json")
    record = read_record(path)
    assert record.training.config.hyper == {"ring": 1}
    assert record.model.hyperparameters["ring"] == 1
    plain = invoke("run", *common, "--evaluators", "torque-error")  # same key, other network
    assert "another configuration" in error_line(plain, 1)


def test_sweep_passes_the_size_to_every_run(smoke_hexa, tmp_path):
    result = invoke(
        "sweep", "--models", "sdnn", "--robots", "hexa", "--preset", "smoke", "--seeds", "0",
        "--evaluators", "torque-error", "--size", "ring=1", "--output", tmp_path,
    )  # fmt: skip
    assert result.exit_code == 0, result.output
    (path,) = tmp_path.glob("*.json")
    assert read_record(path).training.config.hyper == {"ring": 1}


def test_a_keyword_the_model_lacks_is_refused_in_one_line(tmp_path):
    result = invoke("run", "--model", "ffnn", "--robot", "hexa", "--size", "ring=1")
    assert error_line(result, 1) == (
        "Error: model ffnn has no build keyword ring (it has: width, layers)"
    )
    assert "'ring' is not NAME=INT" in error_line(
        invoke("run", "--model", "sdnn", "--robot", "hexa", "--size", "ring"), 2
    )

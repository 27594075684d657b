"""`--size NAME=INT` on run and sweep: a build keyword set by name, kept in the record (and
replayed by `symbench verify`); a keyword the model lacks is refused before any work."""

from __future__ import annotations

from cli_invoke import error_line, invoke

from symbench.core.runs.results import read_record


def test_run_records_the_size_it_was_given_and_its_key_names_it(smoke_hexa, tmp_path):
    """Before 2026-12-06 the key did not name it: the plain run after it was refused, its
    record file holding 'another configuration'."""
    out = tmp_path / "ring"
    common = ("--model", "sdnn", "--robot", "hexa", "--preset", "smoke", "--output", out)
    result = invoke("run", *common, "--size", "ring=1", "--evaluators", "torque-error")
    assert result.exit_code == 0, result.output
    (path,) = out.glob("*.json")
    record = read_record(path)
    assert record.training.config.hyper == {"ring": 1} == record.model.sizes
    assert record.model.hyperparameters["ring"] == 1
    assert path.stem == record.key() and path.stem.endswith("__converge__ring-1__seed0")
    plain = invoke("run", *common, "--evaluators", "torque-error")  # same folder, own record
    assert plain.exit_code == 0, plain.output
    (other,) = set(out.glob("*.json")) - {path}
    assert other.stem == path.stem.replace("__ring-1", "")
    assert read_record(other).model.sizes is None
    assert read_record(other).model.hyperparameters["ring"] == 0


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


def test_a_size_that_cannot_build_the_model_is_refused_naming_the_nearest_that_builds(home):
    """Before: latent=0 trained a zero-width network (torch only warned) and wrote a record."""
    refusals = {
        "latent=0": "--size latent=0: a width of model sdnn/torch is at least 1; nearest "
        "buildable: latent=1",
        "steps=-1": "--size steps=-1: a size of model sdnn/torch is at least 0; nearest "
        "buildable: steps=0",
        "ring=2": "--size ring=2: model sdnn/torch could not be built: SymbenchError: ring must "
        "be 0 or 1, got 2; nearest buildable: ring=1",
        f"latent={10**12}": f"--size latent={10**12}: model sdnn/torch allows at most 64 x its "
        "default; the nearest allowed: latent=8192",
    }
    for size, message in refusals.items():
        result = invoke(
            "run", "--model", "sdnn", "--robot", "hexa", "--preset", "smoke", "--size", size
        )
        assert error_line(result, 1) == f"Error: {message}"
    assert not home.exists()  # refused before any work: no dataset was made


def test_a_parameter_count_no_network_comes_near_is_refused_naming_the_nearest(home):
    """Before: --parameters 3 built a 54-parameter sdnn, 18 times the request, and said
    nothing."""
    result = invoke(
        "run", "--model", "sdnn", "--robot", "hexa", "--preset", "smoke", "--parameters", "3"
    )
    assert error_line(result, 1) == (
        "Error: --parameters 3: the nearest sdnn has 54 parameters (latent=1), 1700% off, "
        "beyond the 10% a matched size allows; nearest buildable: --parameters 54"
    )
    assert not home.exists()

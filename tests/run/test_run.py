"""`symbench run` on the smoke preset: every built-in model on every robot writes a valid record."""

from __future__ import annotations

import hashlib
from pathlib import Path

import pytest
from click.testing import CliRunner

import symbench
from symbench.core.cli import build_cli
from symbench.core.common.errors import SymbenchError, UnknownNameError
from symbench.core.config.presets import dataset_id
from symbench.core.config.provenance import build_hyperparameters, plugin_info
from symbench.core.data.dataset import load_dataset
from symbench.core.plugin import registry
from symbench.core.runs.results import RobotPlugin, read_record
from symbench.core.runs.runner import RunSpec, run

MODELS = ("sdnn", "sdgnn", "ffnn", "ffnn-leg", "gnn")
ROBOTS = ("magneto", "hexa", "nona")
EVALUATORS = ("torque-error", "equivariance", "invariance")


@pytest.mark.parametrize("robot", ROBOTS)
@pytest.mark.parametrize("model", MODELS)
def test_every_model_on_every_robot_writes_a_valid_record(smoke_home, tmp_path, model, robot):
    spec = RunSpec(
        model=model,
        robot=robot,
        preset="smoke",
        evaluators=EVALUATORS,
        output=tmp_path,
        progress=False,
        max_steps=20,
    )
    record = run(spec)
    assert read_record(spec.record_path) == record
    assert record.dataset.id == dataset_id(robot, "smoke")
    assert record.samples.train > 0 and record.samples.test > 0
    assert {f"evaluation_s[{name}]" for name in EVALUATORS} < set(record.timings_s)
    assert record.timings_s["cpu_s"] > 0
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
    result = CliRunner().invoke(
        build_cli(),
        [
            "run",
            "--model",
            "sdnn",
            "--robot",
            "hexa",
            "--preset",
            "smoke",
            "--max-steps",
            "20",
            "--evaluators",
            "torque-error",
            "--output",
            str(tmp_path),
        ],
        catch_exceptions=False,
    )
    assert result.exit_code == 0, result.output
    path = tmp_path / "hexa-climb-smoke-v7__smoke__iid__sdnn__acc__torch__converge__seed0.json"
    record = read_record(path)
    assert record.split == "iid"
    table, written = result.stdout.split("result record:")
    rows = [
        [cell.strip() for cell in line.split(bar)[1:-1]]
        for line in table.splitlines()
        for bar in ("┃", "│")
        if line.count(bar) == 4
    ]
    assert rows == [  # every metric of the record, as it holds it
        ["evaluator", "metric", "value"],
        *(["torque-error", k, f"{v:.4g}"] for k, v in record.metrics["torque-error"].items()),
    ]
    assert ["torque-error", "rmse", f"{record.metrics['torque-error']['rmse']:.4g}"] in rows
    assert "".join(written.split()) == str(path)  # the path, wrapped at the terminal's width
    # where the time went, under the table: the stages, the evaluator's own, the CPU
    timings = record.timings_s
    said = " ".join(table.split("time:")[1].split())
    assert said.startswith(f"dataset {timings['dataset_s']:.0f} s, training ")
    own = timings["evaluation_s[torque-error]"]
    assert f"(torque-error {own:.0f} s); CPU {timings['cpu_s']:.0f} s" in said


def test_names_are_checked_before_any_work(tmp_path):
    with pytest.raises(UnknownNameError, match="did you mean sdnn"):
        run(RunSpec(model="sdn", robot="hexa", output=tmp_path))
    with pytest.raises(UnknownNameError, match="did you mean torque-error"):
        run(RunSpec(model="sdnn", robot="hexa", evaluators=("torque-eror",), output=tmp_path))
    with pytest.raises(SymbenchError, match="preset"):
        run(
            RunSpec(
                model="sdnn",
                robot="hexa",
                preset="huge",
                evaluators=("torque-error",),
                output=tmp_path,
            )
        )
    assert not list(tmp_path.iterdir())


def test_a_run_may_choose_the_next_variant(smoke_home, tmp_path):
    spec = RunSpec(
        model="sdnn",
        robot="hexa",
        preset="smoke",
        variant="next",
        evaluators=("torque-error", "equivariance"),
        output=tmp_path,
        progress=False,
        max_steps=20,
    )
    record = run(spec)
    assert record.model.variant == "next"
    assert (
        spec.record_path.name
        == "hexa-climb-smoke-v7__smoke__iid__sdnn__next__torch__converge__seed0.json"
    )
    assert record.metrics["equivariance"]["max_rel_error"] < 1e-4
    with pytest.raises(UnknownNameError, match="did you mean next"):
        run(RunSpec(model="sdnn", robot="hexa", variant="nxt", output=tmp_path))


@pytest.mark.slow  # the generalization evaluator trains three more models
def test_timings_count_each_second_once(smoke_home, tmp_path):
    record = run(
        RunSpec(
            model="sdnn",
            robot="hexa",
            preset="smoke",
            evaluators=("torque-error", "generalization"),
            output=tmp_path,
            progress=False,
            max_steps=20,
        )
    )
    timings = record.timings_s
    assert timings["retraining_s"] > 0 and timings["evaluation_s"] >= 0
    assert record.training.stopped_early == (record.training.epochs < 2)
    # each evaluator's own seconds, without the three trainings generalization asked for
    own = timings["evaluation_s[torque-error]"] + timings["evaluation_s[generalization]"]
    assert 0 < own <= timings["evaluation_s"] + 1e-6
    assert timings["cpu_s"] > 0


def sha256_of(data: bytes) -> str:
    return hashlib.sha256(data).hexdigest()


def test_a_record_carries_what_it_takes_to_rerun_it(smoke_home, tmp_path):
    spec = RunSpec(
        model="sdnn",
        robot="hexa",
        preset="smoke",
        evaluators=("torque-error",),
        output=tmp_path,
        progress=False,
        max_steps=20,
    )
    record = run(spec)
    package = Path(symbench.__file__).parent / "plugins" / "torch_models"
    sources = "".join(
        f"{p.relative_to(package).as_posix()}\0{sha256_of(p.read_bytes())}\n"
        for p in sorted(package.rglob("*.py"))
    )
    assert record.model.plugin.model_dump() == {
        "module": "symbench.plugins.torch_models.sdnn",
        "distribution": "symbench",
        "version": symbench.__version__,
        "source_sha256": sha256_of(sources.encode()),
    }
    assert record.model.hyperparameters == {
        "latent": 128,
        "mlp_layers": 2,
        "steps": 2,
        "mirror": 0,
        "ring": 0,
    }
    assert record.robot_plugin == RobotPlugin(
        plugin="robots", distribution="symbench", version=symbench.__version__
    )
    assert record.training.config.model_dump() == {
        "seed": 0,
        "batch_size": 64,
        "protocol": "converge",
        "max_steps": 20,
        "eval_every": 10,
        "patience": 2,
        "val_stride": 1,
        "max_epochs": 3,
        "stop_ratio": 0.7,
        "stop_patience": 5,
        "learning_rate": registry.model("sdnn", "torch").learning_rates["hexa"],
        "hyper": {},
        "compile": False,
    }
    t = record.training
    assert (t.steps, t.stopped_by) in ((20, "budget"), (20, "patience"))
    assert t.stop_reason and 0 < t.best_step <= t.steps
    best = next((tmp_path / "checkpoints" / spec.key()).glob("*/iid__acc/best"))
    assert record.training.checkpoint_sha256 == {
        p.name: sha256_of(p.read_bytes()) for p in sorted(best.iterdir())
    }
    assert set(record.training.checkpoint_sha256) >= {"model.safetensors"}
    assert record.dataset.content_hash == load_dataset(record.dataset.id).content_hash


def test_provenance_of_a_third_party_model_and_of_overridden_hyperparameters():
    entry = registry.model("leg-attention", "torch")  # examples/symbench-example-plugin
    info = plugin_info(entry)
    assert (info["distribution"], info["version"]) == ("symbench-example-plugin", "0.1.0")
    assert build_hyperparameters(registry.model("sdnn"), {"latent": 16}) == {
        "latent": 16,
        "mlp_layers": 2,
        "steps": 2,
        "mirror": 0,
        "ring": 0,
    }


@pytest.mark.parametrize(("mirror", "respects_mirrors"), [(0, False), (1, True)])
def test_the_equivariance_evaluator_measures_the_geometry_mirrors_too(
    smoke_home, tmp_path, mirror, respects_mirrors
):
    """hexa's declared group is C6; its geometry, D6, also has six mirrors. The evaluator
    reports them apart: near zero only for the model built for them (sdnn with mirror=1),
    visibly not for plain sdnn, which is equivariant to the rotations either way."""
    record = run(
        RunSpec(
            model="sdnn",
            robot="hexa",
            preset="smoke",
            evaluators=("equivariance",),
            output=tmp_path,
            progress=False,
            max_steps=20,
            sizes=(("mirror", mirror),),
        )
    )
    metrics = record.metrics["equivariance"]
    assert metrics["group"] == "C6" and metrics["geometry_group"] == "D6"
    assert len(metrics["per_element"]) == 6 and len(metrics["mirror_per_element"]) == 6
    assert all(name.startswith("mirror") for name in metrics["mirror_per_element"])
    assert metrics["max_rel_error"] < 1e-4
    if respects_mirrors:
        assert metrics["mirror_max_rel_error"] < 1e-4
    else:
        assert metrics["mirror_max_rel_error"] > 1e-3

"""`symbench verify` reproduces a fresh record exactly and names every metric that differs;
`publish --verify` re-runs a seeded sample of the incoming records before accepting them.

The records are real smoke runs (torque-error only, 2 epochs). Their git commit is set to a
clean one, since this test may run in a working tree with uncommitted changes.
"""

from __future__ import annotations

import importlib
import json
from pathlib import Path

import pytest
from click.testing import CliRunner

from symbench.core.board.publish import publish
from symbench.core.cli import build_cli
from symbench.core.common.errors import SymbenchError
from symbench.core.plugin import registry
from symbench.core.runs import runner
from symbench.core.runs.results import read_record, write_record
from symbench.core.runs.runner import RunSpec, run
from symbench.core.runs.verify import Tolerance, kernel_class_warning, sample

SMOKE = ("smoke",)


@pytest.fixture(scope="module")
def records(smoke_home, tmp_path_factory) -> list[Path]:
    """Three seeds of sdnn on hexa, as a contributor would send them."""
    out = tmp_path_factory.mktemp("contribution")
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(runner, "git_commit", lambda: "1" * 40)
        specs = [
            RunSpec(
                model="sdnn",
                robot="hexa",
                preset="smoke",
                seed=s,
                evaluators=("torque-error",),
                output=out,
                progress=False,
                max_steps=20,
            )
            for s in range(3)
        ]
        for spec in specs:
            run(spec)
    return [spec.record_path for spec in specs]


def resealed(path: Path, folder: Path, change) -> Path:
    """A copy of the record with `change` applied to its torque-error metrics, sealed again."""
    data = json.loads(path.read_text())
    change(data["metrics"]["torque-error"])
    copy = folder / path.name
    write_record(data, copy)
    return copy


def edited(path: Path, folder: Path) -> Path:
    """A copy of the record with its RMSE raised by 1 % (a seal is no signature)."""
    return resealed(path, folder, lambda m: m.update(rmse=m["rmse"] * 1.01))


def verify(*args: str):
    return CliRunner().invoke(build_cli(), ["verify", *args])


def test_a_fresh_record_reproduces_exactly(records):
    result = verify(str(records[0]), "--json")
    assert result.exit_code == 0, result.output
    [report] = json.loads(result.stdout)
    assert report["agree"] and report["tolerance"] == {"rtol": 1e-6, "atol": 1e-12}
    recorded = read_record(records[0]).metrics["torque-error"]
    checks = {c["name"]: c for c in report["metrics"]}
    assert set(checks) == {f"torque-error.{name}" for name in recorded}
    assert all(c["reproduced"] == c["recorded"] for c in checks.values())  # bit for bit
    text = verify(str(records[0]))
    assert text.exit_code == 0
    assert "agreement: |reproduced - recorded| <= 1e-12 + 1e-06 x |recorded|" in text.stdout
    assert f"all {len(checks)} values agree" in text.stdout


def test_an_edited_and_resealed_metric_is_named(records, tmp_path):
    path = edited(records[0], tmp_path)
    result = verify(str(path), "--json")
    assert result.exit_code == 1
    [report] = json.loads(result.stdout)
    assert [c["name"] for c in report["metrics"] if not c["agree"]] == ["torque-error.rmse"]
    text = verify(str(path))
    assert text.exit_code == 1
    assert "1 of 6 values disagree: torque-error.rmse" in " ".join(text.stdout.split())


def test_the_summary_names_the_first_disagreements_and_counts_the_rest(
    records, tmp_path, monkeypatch
):
    """A record made in another kernel class disagrees in hundreds of values: the summary
    line names the first few (the table lists every one), not all of them."""
    monkeypatch.setattr(importlib.import_module("symbench.core.runs.cli.verify"), "SHOWN", 2)
    path = resealed(records[0], tmp_path, lambda m: m.update({k: v + 1 for k, v in m.items()}))
    text = " ".join(verify(str(path)).stdout.split())
    names = list(read_record(records[0]).metrics["torque-error"])  # in the record's order
    first = ", ".join(f"torque-error.{n}" for n in names[:2])
    assert f"6 of 6 values disagree: {first} and 4 more" in text


def test_a_metric_added_since_the_record_is_listed_not_failed(records, tmp_path):
    """A record made before an evaluator gained a value still verifies: the new value is
    shown as not recorded; every value the record has is still compared."""
    name = sorted(read_record(records[0]).metrics["torque-error"])[0]
    path = resealed(records[0], tmp_path, lambda m: m.pop(name))
    result = verify(str(path), "--json")
    assert result.exit_code == 0, result.output
    [report] = json.loads(result.stdout)
    [new] = [c for c in report["metrics"] if not c["recorded_here"]]
    assert new["name"] == f"torque-error.{name}" and new["recorded"] is None
    text = " ".join(verify(str(path)).stdout.split())
    assert "all 5 values agree; 1 values reported today are not in the record" in text
    assert f"torque-error.{name}" in text


def test_a_recorded_metric_the_re_run_lacks_disagrees(records, tmp_path):
    path = resealed(records[0], tmp_path, lambda m: m.update(invented=0.5))
    result = verify(str(path), "--json")
    assert result.exit_code == 1
    [report] = json.loads(result.stdout)
    assert [c["name"] for c in report["metrics"] if not c["agree"]] == ["torque-error.invented"]


def test_tolerance_is_relative_plus_absolute():
    tolerance = Tolerance(rtol=1e-6, atol=1e-12)
    assert tolerance.agree(1.0, 1.0 + 1e-7) and not tolerance.agree(1.0, 1.0 + 1e-5)
    assert tolerance.agree(0.0, 1e-13) and not tolerance.agree(0.0, 1e-11)
    assert tolerance.agree(None, None) and not tolerance.agree(None, 0.0)
    assert not tolerance.agree(True, False)


def test_publish_verifies_a_seeded_sample(records, tmp_path):
    messages: list[str] = []
    board = tmp_path / "leaderboards"
    publish(records, board, presets=SMOKE, verify=1, verify_seed=0, report=messages.append)
    [chosen] = sample(records, 1, seed=0)
    assert messages[0] == f"verifying 1 of 3 records (sample seed 0): {chosen}"
    assert messages[1].startswith(f"{chosen}: all 6 values reproduce")
    assert len(list((board / "records").glob("*.json"))) == 3


def test_publish_refuses_a_sample_that_does_not_reproduce(records, tmp_path):
    folder = tmp_path / "contribution"
    folder.mkdir()
    paths = [folder / p.name for p in records]
    for source, copy in zip(records, paths):
        copy.write_bytes(source.read_bytes())
    [chosen] = sample(paths, 1, seed=0)
    original = read_record(chosen).metrics["torque-error"]["rmse"]
    edited(chosen, folder)
    board = tmp_path / "leaderboards"
    with pytest.raises(SymbenchError) as error:
        publish(paths, board, presets=SMOKE, verify=1, verify_seed=0)
    assert str(error.value) == (
        f"{chosen}: does not reproduce: torque-error.rmse recorded "
        f"{read_record(chosen).metrics['torque-error']['rmse']!r}, reproduced {original!r} "
        f"(agreement: {Tolerance()})"
    )
    assert not board.exists() and [p.name for p in tmp_path.iterdir()] == ["contribution"]


def test_a_record_of_another_dataset_version_is_not_re_run(records, tmp_path):
    data = json.loads(records[0].read_text())
    data["dataset"]["content_hash"] = "ef" * 32
    path = tmp_path / records[0].name
    write_record(data, path)
    result = verify(str(path))
    assert result.exit_code == 1
    here = read_record(records[0]).dataset.content_hash
    assert (
        f"{path}: made on dataset {data['dataset']['id']} with content hash efefefefefef..., "
        f"but this machine generates hash {here[:12]}...; it cannot be reproduced here"
    ) in " ".join(result.output.split())


def test_a_caller_on_other_torch_kernels_still_reproduces_the_record(records, smoke_home):
    """symbench holds torch to its AVX2 kernels whatever the caller's environment says, so a
    maintainer whose environment says otherwise reproduces the record (unpinned, these
    variables change 11 of 14 values of such a record), and is not warned: the record names
    the same kernel class."""
    import os
    import subprocess
    import sys

    from symbench.core.training.kernels import _cpu_has_avx2

    assert _cpu_has_avx2(), "the reference kernels need AVX2"
    env = {
        **os.environ,
        "ATEN_CPU_CAPABILITY": "default",
        "MKL_CBWR": "COMPATIBLE",
        "SYMBENCH_HOME": str(smoke_home),
        "MUJOCO_GL": "disable",
    }
    cli = Path(sys.executable).with_name("symbench")
    out = subprocess.run(
        [str(cli), "verify", str(records[0])], env=env, capture_output=True, text=True, timeout=600
    )
    assert out.returncode == 0, out.stdout + out.stderr
    assert "warning" not in out.stderr and "values agree" in out.stdout


def test_a_record_of_another_model_version_is_refused_not_re_run(records, tmp_path):
    """A record carries its model's version; one made before the network's computation
    changed is refused with both versions named, before anything is trained."""
    here = registry.model("sdnn", "torch").version
    assert read_record(records[0]).model.version == here
    data = json.loads(records[0].read_text())
    data["model"]["version"] = here + 1
    other = write_record(data, tmp_path / records[0].name)
    assert other.configuration()["model version"] == here + 1
    result = verify(str(tmp_path / records[0].name))
    assert result.exit_code == 1
    expected = f"made with sdnn (torch) version {here + 1}, but this code builds version {here}"
    assert expected in " ".join(result.output.split())


def test_a_record_names_its_kernel_class_and_verify_warns_across_classes(records, tmp_path):
    """The record keeps the kernel class it was trained in; a record of another class (or,
    made before classes were recorded, on a CPU of the other vendor) gets a warning that only
    a tolerance can be asked for, and is still re-run and compared."""
    from symbench.core.training.kernels import training_kernels

    here = training_kernels("torch")
    record = read_record(records[0])
    assert record.hardware["training_kernels"] == here
    assert "aten avx2" in here and "1 thread(s)" in here
    intel = "GenuineIntel" in here
    assert ("mkl avx2 strict" in here) == intel  # MKL's AVX2 branch exists on Intel only
    assert kernel_class_warning(record) is None

    data = json.loads(records[0].read_text())
    data["hardware"]["training_kernels"] = "torch 2.13.0+cpu: aten avx2, mkl auto (avx2)"
    write_record(data, tmp_path / "other-class.json")
    warning = kernel_class_warning(read_record(tmp_path / "other-class.json"))
    assert warning and "mkl auto (avx2)" in warning and here in warning
    result = verify(str(tmp_path / "other-class.json"))
    assert result.exit_code == 0 and "agreement within a tolerance only" in result.stderr

    del data["hardware"]["training_kernels"]
    data["hardware"]["cpu"] = "AMD EPYC" if intel else "Intel(R) Xeon(R) Processor"
    write_record(data, tmp_path / "older.json")
    assert "unrecorded, on" in (kernel_class_warning(read_record(tmp_path / "older.json")) or "")
    data["hardware"]["cpu"] = "Intel(R) Xeon(R) Processor" if intel else "AMD EPYC"
    write_record(data, tmp_path / "older-same-vendor.json")
    assert kernel_class_warning(read_record(tmp_path / "older-same-vendor.json")) is None

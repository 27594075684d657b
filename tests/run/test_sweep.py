"""An interrupted sweep resumes without redoing finished runs; it makes every dataset its
runs need before they start."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from dataclasses import replace
from pathlib import Path

import pytest

from symbench.core.runs.results import read_record
from symbench.core.runs.runner import RunSpec
from symbench.core.runs.sweep import plan, sweep

SYMBENCH = str(Path(sys.executable).parent / "symbench")
MODELS = ("sdnn", "ffnn", "ffnn-leg")


def test_interrupted_sweep_resumes_without_redoing_work(smoke_home, tmp_path):
    out = tmp_path / "results"
    command = [
        SYMBENCH,
        "sweep",
        "--models",
        ",".join(MODELS),
        "--robots",
        "hexa",
        "--seeds",
        "0",
        "--preset",
        "smoke",
        "--evaluators",
        "torque-error",
        "--output",
        str(out),
    ]
    proc = subprocess.Popen(
        command,
        env={**os.environ, "SYMBENCH_HOME": str(smoke_home)},
        stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT,
        start_new_session=True,
    )
    deadline = time.monotonic() + 240
    while not list(out.glob("*.json")):
        assert proc.poll() is None, proc.stdout.read().decode()
        assert time.monotonic() < deadline, "the sweep wrote no record in time"
        time.sleep(0.05)
    os.killpg(proc.pid, signal.SIGKILL)  # interrupted mid-sweep, as by a power cut
    proc.wait()
    first = sorted(out.glob("*.json"))
    assert 1 <= len(first) < len(MODELS)
    before = {p: (p.stat().st_mtime_ns, p.read_bytes()) for p in first}

    base = RunSpec(
        model="", robot="", preset="smoke", evaluators=("torque-error",), output=out, progress=False
    )
    specs = plan(MODELS, ["hexa"], ["iid"], [0], ["torch"], base)
    messages: list[str] = []
    ran = sweep(specs, report=messages.append)
    assert messages[0].startswith(f"{len(first)} of {len(MODELS)} runs already have records")
    assert sorted(ran) == sorted(s.key() for s in specs if s.record_path not in before)
    for path, (mtime, content) in before.items():  # finished runs were not redone
        assert (path.stat().st_mtime_ns, path.read_bytes()) == (mtime, content)
    assert all(read_record(s.record_path).model.name == s.model for s in specs)
    assert sweep(specs, report=messages.append) == []  # a finished sweep does nothing


@pytest.mark.slow  # minutes on 2 cores: kept out of the default suite's 10
def test_sweep_on_a_local_ray_cluster(smoke_home, tmp_path):
    import ray

    base = RunSpec(
        model="",
        robot="",
        preset="smoke",
        evaluators=("torque-error",),
        output=tmp_path,
        progress=False,
    )
    specs = plan(("sdnn", "ffnn"), ["hexa"], ["iid"], [0], ["torch"], base)
    try:
        ran = sweep(specs, executor="ray", report=lambda message: None)
    finally:
        ray.shutdown()
    assert sorted(ran) == sorted(s.key() for s in specs)
    assert [read_record(s.record_path).model.name for s in specs] == ["sdnn", "ffnn"]


def test_a_sweep_makes_the_data_its_evaluators_train_on_before_any_run(
    smoke_home, tmp_path, monkeypatch
):
    """The closed loop trains on the noisy variant: the sweep makes it first, with its own
    workers, instead of letting parallel runs race to simulate it."""
    import shutil

    from symbench.core.runs import sweep as sweeping
    from symbench.core.runs.planning import declared_datasets
    from symbench.core.runs.spec import ensure_dataset

    home = tmp_path / "home"
    shutil.copytree(
        smoke_home / "datasets" / "hexa-climb-smoke-v7", home / "datasets" / "hexa-climb-smoke-v7"
    )
    monkeypatch.setenv("SYMBENCH_HOME", str(home))
    noisy = home / "datasets" / "hexa-climb-smoke-noisy-v7"
    seen: list[bool] = []
    monkeypatch.setattr(
        sweeping, "_run_quietly", lambda spec: seen.append(noisy.is_dir()) or spec.key()
    )
    base = RunSpec(
        model="", robot="", preset="smoke", evaluators=("torque-error",), output=tmp_path / "out"
    )
    plain = plan(("sdnn", "ffnn"), ["hexa"], ["iid"], [0], ["torch"], base)
    assert declared_datasets(plain[0], ensure_dataset(plain[0])) == []
    sweep(plain, report=lambda message: None)
    assert seen == [False, False]  # no evaluator asked for it: not made

    controlled = [replace(s, evaluators=("torque-error", "closed-loop")) for s in plain]
    dataset = ensure_dataset(controlled[0])
    with monkeypatch.context() as no_views:  # planning builds no samples (paper: ~20 s a run)
        no_views.setattr(type(dataset), "view", lambda *a, **k: pytest.fail("built a view"))
        assert declared_datasets(controlled[0], dataset) == ["hexa-climb-smoke-noisy-v7"]
    seen.clear()
    sweep(controlled, report=lambda message: None)
    assert seen == [True, True]


@pytest.mark.slow  # a sweep of real runs
def test_a_sweeps_step_budget_reaches_every_run(smoke_home, tmp_path):
    """`--max-steps` of a sweep is every run's budget, recorded; a sweep without it uses the
    preset's."""
    out = tmp_path / "results"
    common = ["--robots", "hexa", "--seeds", "0", "--preset", "smoke"]
    common += ["--evaluators", "torque-error", "--output", str(out)]
    env = {**os.environ, "SYMBENCH_HOME": str(smoke_home)}
    for model, budget in (("ffnn", ["--max-steps", "7"]), ("ffnn-leg", [])):
        done = subprocess.run(
            [SYMBENCH, "sweep", "--models", model, *common, *budget],
            env=env,
            capture_output=True,
            text=True,
        )
        assert done.returncode == 0, done.stdout + done.stderr
    records = {r.model.name: r for r in map(read_record, out.glob("*.json"))}
    assert records["ffnn"].training.config.max_steps == 7
    assert records["ffnn"].training.steps <= 7
    assert records["ffnn-leg"].training.config.max_steps == 30  # smoke's budget

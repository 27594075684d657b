"""`symbench bench models`: FLOP counts that add up, and a report whose every share of the
matmul rate divides by the best rate measured with the same threads."""

from __future__ import annotations

import json
import os

import pytest
import torch
from click.testing import CliRunner

from symbench.core.bench.flops import step_flops_per_sample
from symbench.core.bench.threads import ThreadCounts
from symbench.core.cli import build_cli
from symbench.core.data.views.model_dims import dims_for
from symbench.core.plugin import registry
from symbench.core.training.backends.torch_backend import build_network
from symbench.core.training.kernels import TORCH_PINS, XLA_PIN, XLA_POOL

BATCH = 8


def test_torch_flops_of_an_mlp_are_its_matmuls_forward_and_backward():
    """Each Linear layer: 2io forward, 2io for its weight gradient, 2io for its input's
    gradient except the first layer's (the data needs none): per sample."""
    entry = registry.model("ffnn", "torch")
    dims = dims_for(entry.view, entry.variant, 6)
    layers = [m for m in build_network(entry, dims, {}).modules() if isinstance(m, torch.nn.Linear)]
    expected = sum(6 * m.in_features * m.out_features for m in layers)
    expected -= 2 * layers[0].in_features * layers[0].out_features
    assert step_flops_per_sample(entry, dims, BATCH) == expected


@pytest.mark.parametrize("name", ["sdnn", pytest.param("ffnn", marks=pytest.mark.slow)])
def test_both_backends_count_nearly_the_same_flops(name):
    """XLA also counts elementwise operations; the matmuls dominate, so within 10%."""
    torch_entry, jax_entry = registry.model(name, "torch"), registry.model(name, "jax")
    dims = dims_for(torch_entry.view, torch_entry.variant, 6)
    by_torch = step_flops_per_sample(torch_entry, dims, BATCH)
    by_jax = step_flops_per_sample(jax_entry, dims, BATCH)
    assert by_torch > 0 and abs(by_jax - by_torch) / by_torch < 0.1


@pytest.mark.slow  # minutes on 2 cores: kept out of the default suite's 10
def test_the_report_of_both_thread_settings():
    """One short run (each setting a child process; one model, so it stays short), checked
    for every property the report promises."""
    args = ["bench", "models", "--models", "ffnn", "--seconds", "0.05", "--json"]
    result = CliRunner().invoke(build_cli(), args)
    assert result.exit_code == 0, result.output
    report = json.loads(result.stdout)
    assert report["lockstep_batch"] == 32 * 4  # small's references x its PD fractions
    _each_setting_ran_with_the_threads_it_states(report["settings"])
    for setting in report["settings"]:
        _every_share_divides_by_the_best_matmul_rate_of_its_setting(setting)
        _the_matmul_rates_are_those_of_the_training_kernels(setting)
    _latency_is_measured_with_the_fewest_threads_only(report["settings"])
    assert "1 thread: [2/2] ffnn/jax: training, compiled" in result.stderr


def _each_setting_ran_with_the_threads_it_states(settings):
    """One thread and every core this process may use (one setting on a single core), and
    each child computed with that many cores: torch with as many threads, XLA with the pool
    training runs (`kernels.XLA_POOL`), whose size shapes the step it compiles."""
    assert [s["threads"] for s in settings] == sorted({1, len(os.sched_getaffinity(0))})
    for setting in settings:
        n = setting["threads"]
        assert len(setting["cores"]) == n
        assert setting["threads_used"] == {"torch": n, "jax": int(XLA_POOL["NPROC"])}


def _every_share_divides_by_the_best_matmul_rate_of_its_setting(setting):
    matmul = setting["matmul_flops_per_s"]
    assert set(matmul) == {"torch", "jax"} and min(matmul.values()) > 0
    best = max(matmul.values())
    assert matmul[setting["best_matmul_backend"]] == best
    rows = setting["rows"]
    assert [(r["model"], r["backend"]) for r in rows] == [("ffnn", "torch"), ("ffnn", "jax")]
    for row in rows:
        mode = row["train_best"]
        assert mode == ("plain" if row["backend"] == "torch" else "compiled")
        rate = row[f"train_samples_per_s_{mode}"]
        assert row["train_flops_per_s"] == pytest.approx(rate * row["train_flops_per_sample"])
        own = row["train_flops_per_s"] / matmul[row["backend"]]
        assert row["share_of_own_matmul"] == pytest.approx(own)
        assert row["share_of_best_matmul"] == pytest.approx(row["train_flops_per_s"] / best)
        # a plausible share: on a machine busy with other work a matmul window can fall on a
        # busy moment (2.7 measured while a sweep ran), but a unit slip (FLOPs per batch of
        # 64, not per sample) lands far above 10
        assert 0 < row["share_of_best_matmul"] <= row["share_of_own_matmul"] < 10


def _the_matmul_rates_are_those_of_the_training_kernels(setting):
    """The children run under the pins training runs under (this CPU has AVX2)."""
    pins = setting["kernel_pins"]
    assert {k: pins[k] for k in TORCH_PINS} == TORCH_PINS
    assert {k: pins[k] for k in XLA_POOL} == XLA_POOL
    assert pins["torch_cpu_capability"] == "AVX2" and XLA_PIN in pins["XLA_FLAGS"]


def _latency_is_measured_with_the_fewest_threads_only(settings):
    first, *others = settings
    assert first["latency_measured"]
    assert all(r[f"infer_batch1_us_{r['infer_best']}"] > 0 for r in first["rows"])
    assert all(r[f"infer_lockstep_us_{r['lockstep_best']}"] > 0 for r in first["rows"])
    # torch rows also time their ONNX export under ONNX Runtime, JAX rows do not
    assert all(("infer_batch1_us_onnx" in r) == (r["backend"] == "torch") for r in first["rows"])
    # an evaluator's call, in the backend's own mode (evaluators never call ONNX Runtime)
    assert all(r[f"predict_rows_per_s_{r['train_best']}"] > 0 for r in first["rows"])
    assert not any("predict_rows_per_s_onnx" in r for r in first["rows"])
    for setting in others:
        assert not setting["latency_measured"]
        assert not any(k.startswith(("infer", "predict")) for r in setting["rows"] for k in r)


@pytest.mark.parametrize(
    ("threads", "message"),
    [
        ("0", "0 threads: a setting needs at least 1"),
        ("abc", "'abc' is neither a number of threads nor 'all'"),
        (",", "',' names nothing"),
        ("4096", "4096 threads: this process may use only"),
    ],
)
def test_a_bad_thread_setting_is_refused_before_any_work(threads, message):
    result = CliRunner().invoke(build_cli(), ["bench", "models", "--threads", threads])
    assert result.exit_code == 2 and message in result.stderr, result.output


def test_thread_settings_are_sorted_and_name_each_count_once():
    cores = len(os.sched_getaffinity(0))
    assert ThreadCounts().convert("all,1", None, None) == sorted({1, cores})
    assert ThreadCounts().convert(f"{cores}, all,", None, None) == [cores]

"""Bad input from a user or a file is one line naming the input and the problem: exit status 2
for a malformed command line, 1 for a failure; a traceback only with --debug."""

from __future__ import annotations

import json
import re

import click
import numpy as np
import pytest
from bad_plugins import bad_plugin_installed
from cli_invoke import error_line, invoke
from synthetic_raw import write_logs

from symbench import hookimpl
from symbench.core.common.errors import SymbenchError
from symbench.core.data.storage.metadata import METADATA, content_hash
from symbench.core.plugin.host import PluginHost, set_host
from symbench.core.runs import runner
from symbench.core.runs.cli import run as run_command
from symbench.core.runs.results import write_record
from symbench.core.training.checkpoints import write_tensors
from symbench.core.training.trained_model import TENSORS, TrainedModel

DEEP = "[" * 100_000 + "]" * 100_000


@pytest.fixture
def no_run(monkeypatch):
    """`symbench run` fails the test if it gets as far as running."""

    def never(*args, **kwargs):
        raise AssertionError("the run started")

    monkeypatch.setattr(run_command, "run_spec", never)
    monkeypatch.setattr(runner, "ensure_dataset", never)


@pytest.mark.parametrize(
    "args,option",
    [
        (("run", "--model", "sdnn", "--robot", "hexa", "--seed", 2**32), "--seed"),
        (("sweep", "--models", "sdnn", "--robots", "hexa", "--seeds", f"0,{2**32}"), "--seeds"),
        (("data", "info", "hexa-climb-smoke-v7", "--seed", 2**32), "--seed"),
    ],
)
def test_a_seed_beyond_2_32_is_a_usage_error(no_run, args, option):
    assert error_line(invoke(*args), 2) == (
        f"Error: Invalid value for '{option}': {2**32} is not in the range 0<=x<=4294967295."
    )


@pytest.mark.parametrize("period", ["nan", "inf"])
def test_sim_check_refuses_a_control_period_that_is_not_finite(period):
    message = error_line(
        invoke("sim", "check", "--robot", "hexa", "--seconds", "0.01", "--control-period", period),
        2,
    )
    assert message == (
        f"Error: Invalid value for '--control-period': '{period}' is not a finite number"
    )


@pytest.mark.parametrize(
    "where,reason", [("a file", "File exists"), ("a folder under a file", "Not a directory")]
)
def test_an_output_folder_that_cannot_take_files_is_refused_before_any_work(
    no_run, tmp_path, where, reason
):
    blocker = tmp_path / "results.txt"
    blocker.write_text("not a folder")
    output = blocker if where == "a file" else blocker / "results"
    message = error_line(invoke("run", "--model", "sdnn", "--robot", "hexa", "--output", output), 2)
    assert message == (
        f"Error: Invalid value for '--output': '{output}': cannot write there ({reason})"
    )


def test_symbench_home_pointing_to_a_file_is_named(tmp_path, monkeypatch):
    home = tmp_path / "home"
    home.write_text("not a folder")
    monkeypatch.setenv("SYMBENCH_HOME", str(home))
    message = error_line(invoke("data", "import", write_logs(tmp_path / "logs"), "--id", "logs"), 1)
    assert (
        f"Error: symbench's home {home} (SYMBENCH_HOME) cannot be a folder: {home} is a file"
        == message
    )


def test_leaderboard_out_naming_a_file_is_a_usage_error(tmp_path, make_record):
    write_record(make_record(), tmp_path / "results" / "r.json")
    out = tmp_path / "board.md"
    out.write_text("not a folder")
    message = error_line(invoke("leaderboard", "--results", tmp_path / "results", "--out", out), 2)
    assert message == f"Error: Invalid value for '--out': '{out}': cannot write there (File exists)"


@pytest.mark.parametrize("key", ["n_legs", "trajectories", "repair_command"])
def test_metadata_missing_a_key_is_named(smoke_hexa, key):
    path = smoke_hexa.root / METADATA
    meta = json.loads(path.read_text())
    del meta[key]
    meta["content_hash"] = content_hash(meta)  # re-hashed, as a careful forger would
    path.write_text(json.dumps(meta))
    message = error_line(invoke("data", "info", smoke_hexa.dataset_id), 1)
    assert message == (
        f"Error: dataset '{smoke_hexa.dataset_id}': {path} is malformed: {key}: Field required"
    )


@pytest.mark.parametrize(
    "edit,problem",
    [
        (
            lambda m: m.update(record_period_s=float("inf")),
            "import: {path}: not valid JSON (Infinity is not a JSON number)",
        ),
        (
            lambda m: m.update(
                trajectories=[{"file": "run0.npz", "scenario": {"heading_deg": float("nan")}}]
            ),
            "import: {path}: not valid JSON (NaN is not a JSON number)",
        ),
        (
            lambda m: m.update(record_period_s="0.006"),
            "{path}: record_period_s: Input should be a valid number, got '0.006'",
        ),
        (
            lambda m: m.update(trajectories=[{"file": 7}]),
            "{path}: trajectories.0.file (file 7): Input should be a valid string, got 7",
        ),
        (
            lambda m: m.update(trajectories=[{"file": "run0.npz", "scenario": [1]}]),
            "{path}: trajectories.0.scenario (file run0.npz): Input should be a valid dictionary "
            "or instance of ScenarioFields",
        ),
        (
            lambda m: m.update(
                trajectories=[{"file": "run0.npz", "scenario": {"heading_deg": 2**53 + 1}}]
            ),
            "{path}: trajectories.0.scenario.heading_deg (file run0.npz): 9007199254740993 has "
            "more digits than a float holds: give it as a float, got 9007199254740993",
        ),
    ],
    ids=[
        "Infinity",
        "NaN",
        "text for a number",
        "number for a file",
        "list for a scenario",
        "an integer no float holds",
    ],
)
def test_import_json_with_bad_values_is_named(home, tmp_path, edit, problem):
    folder = write_logs(tmp_path / "logs")
    manifest = json.loads((folder / "import.json").read_text())
    edit(manifest)
    (folder / "import.json").write_text(json.dumps(manifest))  # writes Infinity and NaN as such
    message = error_line(invoke("data", "import", folder), 1)
    assert message == "Error: " + problem.format(path=folder / "import.json")
    assert not (home / "datasets").exists()


def test_import_json_nested_too_deeply_is_named(home, tmp_path):
    folder = write_logs(tmp_path / "logs")
    (folder / "import.json").write_text(DEEP)
    message = error_line(invoke("data", "import", folder), 1)
    assert message == f"Error: import: {folder / 'import.json'}: not valid JSON (nested too deeply)"


def test_sweep_seeds_that_are_not_numbers_are_a_usage_error():
    message = error_line(
        invoke("sweep", "--models", "sdnn", "--robots", "hexa", "--seeds", "0,one"), 2
    )
    assert message == "Error: Invalid value for '--seeds': 'one' is not a valid integer range."


@pytest.mark.parametrize(
    "content,reason",
    [
        (DEEP, re.escape("nested too deeply")),
        ("9" * 5000, r"Exceeds the limit \(4300 digits\) for integer string conversion.*"),
    ],
    ids=["deep nesting", "5000 digits"],
)
def test_an_unreadable_json_file_among_results_is_named(tmp_path, make_record, content, reason):
    write_record(make_record(), tmp_path / "results" / "r.json")
    (tmp_path / "results" / "s.json").write_text(content)
    message = error_line(
        invoke("leaderboard", "--results", tmp_path / "results", "--out", tmp_path / "board"), 1
    )
    path = re.escape(str(tmp_path / "results" / "s.json"))
    assert re.fullmatch(
        rf"Error: cannot read result record {path}: not valid JSON \({reason}\)", message
    ), message


def test_a_crafted_checkpoint_is_refused_naming_it(tmp_path):
    """Hashed like a real one (anyone can compute a SHA-256), so only its content can tell."""
    path = tmp_path / TENSORS
    write_tensors(path, {"params/w": np.zeros(3)}, {"format": "symbench-model/1"})
    with pytest.raises(
        SymbenchError, match=f"{path}: malformed model description: model: Field required"
    ):
        TrainedModel.load(tmp_path)
    path.write_bytes(len(DEEP).to_bytes(8, "little") + DEEP.encode())  # a header nested deeply
    with pytest.raises(
        SymbenchError,
        match=f"checkpoint {path} is not a readable safetensors "
        r"file \(nested too deeply\)",
    ):
        TrainedModel.load(tmp_path)


def test_a_plugin_hook_that_returns_no_list_breaks_no_other_command():
    with bad_plugin_installed():
        result = invoke("list", "robots", "--json")
    assert result.exit_code == 0, result.output
    assert {r["name"] for r in json.loads(result.stdout)} == {"magneto", "hexa", "nona"}
    assert result.stderr == (
        "warning: plugin 'bad' failed in symbench_robots: returned RobotEntry, expected a "
        "list of RobotEntry\n"
    )


@pytest.mark.parametrize("backend", ["torch", "jax"])
def test_a_model_with_misshaped_torques_is_one_line(smoke_hexa, tmp_path, backend):
    with bad_plugin_installed():
        message = error_line(
            invoke(
                "run",
                "--model",
                "flat-net",
                "--backend",
                backend,
                "--robot",
                "hexa",
                "--preset",
                "smoke",
                "--evaluators",
                "torque-error",
                "--output",
                tmp_path,
            ),
            1,
        )
    assert re.fullmatch(
        rf"Error: model flat-net/{backend} returned torques shaped \((\d+), 18\), "
        r"expected \(\1, 6, 3\) \(N, n_legs, 3\)",
        message,
    ), message


def test_an_evaluator_that_returns_no_mapping_is_named(smoke_hexa, tmp_path):
    with bad_plugin_installed():
        message = error_line(
            invoke(
                "run",
                "--model",
                "ffnn",
                "--robot",
                "hexa",
                "--preset",
                "smoke",
                "--evaluators",
                "pairs",
                "--output",
                tmp_path,
            ),
            1,
        )
    assert message == (
        "Error: evaluator 'pairs' returned list, expected a mapping of metric names (str) to values"
    )


def test_an_evaluator_whose_declared_trainings_fail_is_named(smoke_hexa, tmp_path):
    with bad_plugin_installed():
        message = error_line(
            invoke(
                "run",
                "--model",
                "ffnn",
                "--robot",
                "hexa",
                "--preset",
                "smoke",
                "--evaluators",
                "plans-badly",
                "--output",
                tmp_path,
            ),
            1,
        )
    assert message == "Error: evaluator 'plans-badly': trainings() failed: KeyError: 'split'"


def test_an_evaluator_that_plans_from_test_samples_is_told_why_it_cannot(smoke_hexa, tmp_path):
    """A sweep plans every run before any starts, without their samples (a `paper` view costs
    tens of seconds); an evaluator that reads them while planning is told so."""
    with bad_plugin_installed():
        command = ["sweep", "--models", "ffnn", "--robots", "hexa", "--preset", "smoke"]
        result = invoke(*command, "--evaluators", "plans-from-samples", "--output", tmp_path)
    message = error_line(result, 1)
    assert message.startswith(
        "Error: evaluator 'plans-from-samples': trainings() runs while a sweep plans, before "
        "the test samples are made"
    )


class Crashing:
    @hookimpl
    def symbench_commands(self, cli: click.Group) -> None:
        @cli.command("crash")
        def crash() -> None:
            raise RuntimeError("a bug")


def test_an_unexpected_error_is_one_line_and_debug_shows_its_traceback():
    host = PluginHost()
    host.load_entry_points("none")
    host.register(Crashing(), "crashing")
    set_host(host)
    try:
        message = error_line(invoke("crash"), 1)
        assert message == (
            "Error: internal error: RuntimeError: a bug (run with --debug for the traceback)"
        )
        with pytest.raises(AssertionError, match="RuntimeError: a bug"):
            invoke("--debug", "crash")
    finally:
        set_host(None)


@pytest.mark.parametrize("value", ["", "two", "0", "-1", "1.5"])
def test_torch_threads_that_are_no_thread_count_are_named(value, monkeypatch):
    from symbench.core.training.backends.torch_backend import _torch_threads

    monkeypatch.setenv("SYMBENCH_TORCH_THREADS", value)
    with pytest.raises(SymbenchError) as error:
        _torch_threads()
    assert str(error.value) == (
        f"SYMBENCH_TORCH_THREADS must be a positive whole number, not {value!r}"
    )
    monkeypatch.setenv("SYMBENCH_TORCH_THREADS", "2")
    assert _torch_threads() == 2

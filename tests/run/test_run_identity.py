"""A run's identity is its whole configuration, and a run can use any dataset.

Record files are named by dataset, preset, split, model, variant, backend and seed, so runs on
other data or budgets never overwrite each other; a sweep counts a run as finished only when
the record at its path holds the requested configuration, and refuses (or, with --overwrite,
replaces) a record of another one; `--dataset` trains on an imported dataset from the command
line, and boards group records by dataset.

The datasets are made by the stand-in simulator (the same files and ids as the real ones, in
seconds) and the `small` preset's epoch cap is lowered to one epoch, so every run here takes
seconds.
"""

from __future__ import annotations

import dataclasses
import json
from pathlib import Path

import pytest
from cli_invoke import error_line, invoke
from synthetic_raw import fake_simulate

from symbench.core.common.errors import SymbenchError
from symbench.core.config.presets import PRESETS, Training
from symbench.core.data.dataset import load_dataset
from symbench.core.data.generation.generate import generate
from symbench.core.data.importing.importer import export_dataset, import_logs
from symbench.core.runs.results import read_record, write_record
from symbench.core.runs.runner import RunSpec, run
from symbench.core.runs.sweep import plan, sweep

SMOKE = "hexa-climb-smoke-v7"
SMALL = "hexa-climb-small-v7"
LOGS = "hexa-logs"  # imported: the smoke trajectories exported and imported again


def key(
    dataset: str,
    preset: str,
    model: str = "sdnn",
    seed: int = 0,
    variant: str = "acc",
    protocol: str = "converge",
) -> str:
    return f"{dataset}__{preset}__iid__{model}__{variant}__torch__{protocol}__seed{seed}"


@pytest.fixture(scope="module")
def data_home(tmp_path_factory):
    """A symbench home holding hexa's smoke and small datasets and the imported `hexa-logs`."""
    home = tmp_path_factory.mktemp("identity-home")
    with pytest.MonkeyPatch.context() as patch:
        patch.setenv("SYMBENCH_HOME", str(home))
        for grid in ("smoke", "small"):
            generate("hexa", grid, simulator=fake_simulate, show_progress=False)
        logs = export_dataset(load_dataset(SMOKE), home.parent / "hexa-logs-export")
        import_logs(logs, LOGS)
        yield home


@pytest.fixture
def home(data_home, monkeypatch):
    """`data_home`, with the small preset's epoch cap lowered to 1 (its budgets otherwise)."""
    monkeypatch.setenv("SYMBENCH_HOME", str(data_home))
    small = PRESETS["small"]
    monkeypatch.setitem(
        PRESETS, "small", dataclasses.replace(small, training=Training(10, 10, 1, 1))
    )
    return data_home


def run_command(out: Path, *args: str):
    result = invoke(
        "run", "--model", "sdnn", "--evaluators", "torque-error", "--output", out, *args
    )
    assert result.exit_code == 0, result.output
    return result


def sweep_command(out: Path, *args: str):
    return invoke(
        "sweep",
        "--models",
        "sdnn",
        "--seeds",
        "0",
        "--evaluators",
        "torque-error",
        "--output",
        out,
        *args,
    )


def test_the_key_names_the_record_file_and_comes_from_the_records_fields(make_record, tmp_path):
    record = write_record(make_record(model="gnn", seed=4), tmp_path / "r.json")
    assert record.key() == key(SMOKE, "smoke", "gnn", 4, protocol="paper")  # its config's
    spec = RunSpec(model="gnn", robot="hexa", preset="smoke", seed=4, output=tmp_path)
    assert spec.record_path == tmp_path / f"{key(SMOKE, 'smoke', 'gnn', 4)}.json"
    other = RunSpec(model="gnn", robot="hexa", dataset=LOGS, preset="smoke", seed=4)
    assert other.key() == key(LOGS, "smoke", "gnn", 4)


def test_a_small_run_does_not_overwrite_the_smoke_record_of_the_same_model(home, tmp_path):
    out = tmp_path / "results"
    run_command(out, "--robot", "hexa", "--preset", "smoke")
    smoke = out / f"{key(SMOKE, 'smoke')}.json"
    before = smoke.read_bytes()
    result = run_command(out, "--robot", "hexa")  # the default preset, small
    small = out / f"{key(SMALL, 'small')}.json"
    assert f"result record: {small}\n" in result.stdout
    assert smoke.read_bytes() == before
    assert sorted(p.name for p in out.glob("*.json")) == sorted([smoke.name, small.name])
    assert [read_record(p).dataset.preset for p in (smoke, small)] == ["smoke", "small"]
    assert [read_record(p).dataset.id for p in (smoke, small)] == [SMOKE, SMALL]
    # checkpoints are kept apart too
    assert sorted(p.name for p in (out / "checkpoints").iterdir()) == sorted(
        [key(SMOKE, "smoke"), key(SMALL, "small")]
    )


def test_a_sweep_on_an_earlier_dataset_versions_preset_writes_its_records(home, tmp_path):
    """`sweep --preset small@v6` (the v6 board's data and budgets) once trained and evaluated
    its first run and then failed to write the record: its preset field refused the '@'."""
    generate("hexa", "smoke@v6", simulator=fake_simulate, show_progress=False)
    out, name = tmp_path / "results", key("hexa-climb-smoke-v6", "smoke@v6")
    result = sweep_command(out, "--robots", "hexa", "--preset", "smoke@v6")
    assert result.exit_code == 0, result.output
    assert result.stdout.splitlines() == [
        "0 of 1 runs already have records; 1 to run",
        f"finished {name}",
    ]
    record = read_record(out / f"{name}.json")
    assert (record.dataset.id, record.dataset.preset) == ("hexa-climb-smoke-v6", "smoke@v6")
    again = sweep_command(out, "--robots", "hexa", "--preset", "smoke@v6")
    assert again.stdout.splitlines() == ["1 of 1 runs already have records; 0 to run"]


def test_a_sweep_runs_what_another_presets_record_does_not_hold(home, tmp_path):
    """The issue's case: a smoke record in the folder, `sweep --preset small` of the same
    model once printed '1 of 1 runs already have records; 0 to run'."""
    out = tmp_path / "results"
    run_command(out, "--robot", "hexa", "--preset", "smoke")
    smoke = out / f"{key(SMOKE, 'smoke')}.json"
    before = smoke.read_bytes()
    result = sweep_command(out, "--robots", "hexa", "--preset", "small")
    assert result.exit_code == 0, result.output
    assert result.stdout.splitlines() == [
        "0 of 1 runs already have records; 1 to run",
        f"finished {key(SMALL, 'small')}",
    ]
    assert read_record(out / f"{key(SMALL, 'small')}.json").dataset.preset == "small"
    assert smoke.read_bytes() == before
    again = sweep_command(out, "--robots", "hexa", "--preset", "small")
    assert again.stdout.splitlines() == ["1 of 1 runs already have records; 0 to run"]


def test_a_sweep_with_the_next_variant_keeps_its_records_apart(home, tmp_path):
    """`sweep --variant next` (the closed loop's control runs) trains every run on the next
    variant, under keys of their own beside the default variant's records."""
    out = tmp_path / "results"
    assert sweep_command(out, "--robots", "hexa", "--preset", "smoke").exit_code == 0
    result = sweep_command(out, "--robots", "hexa", "--preset", "smoke", "--variant", "next")
    assert result.exit_code == 0, result.output
    nxt = out / f"{key(SMOKE, 'smoke', variant='next')}.json"
    assert result.stdout.splitlines()[-1] == f"finished {nxt.stem}"
    assert read_record(nxt).model.variant == "next"
    assert read_record(out / f"{key(SMOKE, 'smoke')}.json").model.variant == "acc"


def test_a_record_of_another_configuration_is_refused_or_replaced(home, tmp_path):
    out = tmp_path / "results"
    assert sweep_command(out, "--robots", "hexa", "--preset", "smoke").exit_code == 0
    path = out / f"{key(SMOKE, 'smoke')}.json"
    before = path.read_bytes()
    more = ("--robots", "hexa", "--preset", "smoke", "--evaluators", "torque-error,invariance")
    assert error_line(sweep_command(out, *more), 1) == (
        f"Error: {path} is a record of another configuration (evaluators torque-error in the "
        "record, invariance,torque-error in this run); pass --overwrite to run it again and "
        "replace it, or choose another --output"
    )
    assert path.read_bytes() == before  # nothing ran
    # `symbench run` refuses too, before any work
    fewer_steps = ("--robot", "hexa", "--preset", "smoke", "--max-steps", "10")
    message = error_line(
        invoke(
            "run", "--model", "sdnn", *fewer_steps, "--evaluators", "torque-error", "--output", out
        ),
        1,
    )
    assert message == (
        f"Error: {path} is a record of another configuration (training max_steps 30 in the "
        "record, 10 in this run); pass --overwrite to run it again and replace it, or choose "
        "another --output"
    )
    result = sweep_command(out, *more, "--overwrite")
    assert result.exit_code == 0, result.output
    assert result.stdout.splitlines() == [
        "0 of 1 runs already have records; 1 to run",
        f"replacing {path} (--overwrite): evaluators torque-error in the record, "
        "invariance,torque-error in this run",
        f"finished {key(SMOKE, 'smoke')}",
    ]
    assert list(read_record(path).metrics) == ["torque-error", "invariance"]


def test_a_record_made_on_other_data_under_the_same_id_is_not_finished(home, tmp_path):
    """A regenerated (or re-imported) dataset keeps its id but not its content hash."""
    out = tmp_path / "results"
    assert sweep_command(out, "--datasets", LOGS, "--preset", "smoke").exit_code == 0
    path = out / f"{key(LOGS, 'smoke')}.json"
    data = json.loads(path.read_text())
    data["dataset"]["content_hash"] = "ef" * 32
    write_record(data, path)  # sealed again: a valid record of other data
    here = load_dataset(LOGS).content_hash
    assert error_line(sweep_command(out, "--datasets", LOGS, "--preset", "smoke"), 1) == (
        f"Error: {path} is a record of another configuration (dataset content hash "
        f"efefefefefef... in the record, {here[:12]}... in this run); pass --overwrite to run "
        "it again and replace it, or choose another --output"
    )
    assert sweep_command(out, "--datasets", LOGS, "--preset", "smoke", "--overwrite").exit_code == 0
    assert read_record(path).dataset.content_hash == here


def test_a_corrupt_record_is_run_again(home, tmp_path):
    base = RunSpec(
        model="", robot="", preset="smoke", evaluators=("torque-error",), output=tmp_path
    )
    [spec] = plan(["sdnn"], ["hexa"], ["iid"], [0], ["torch"], base)
    spec.record_path.write_text("{}")
    messages: list[str] = []
    assert sweep([spec], report=messages.append) == [spec.key()]
    assert messages[0] == "0 of 1 runs already have records; 1 to run"
    assert messages[1].startswith("running again: result record ")
    assert read_record(spec.record_path).model.name == "sdnn"


def test_run_on_an_imported_dataset_from_the_command_line(home, tmp_path):
    out = tmp_path / "results"
    result = run_command(out, "--dataset", LOGS, "--preset", "smoke")  # no --robot: the data's
    assert f"sdnn on {LOGS} (hexa, preset smoke)" in result.stdout
    path = out / f"{key(LOGS, 'smoke')}.json"
    record = read_record(path)
    assert (record.robot, record.dataset.id, record.dataset.preset) == ("hexa", LOGS, "smoke")
    assert record.dataset.content_hash == load_dataset(LOGS).content_hash
    assert record.samples.train > 0
    # the preset defaults to small for imported data; --robot, when given, must agree
    run_command(out, "--dataset", LOGS, "--robot", "hexa")
    assert read_record(out / f"{key(LOGS, 'small')}.json").training.config.max_steps == 10
    assert error_line(
        invoke("run", "--model", "sdnn", "--dataset", LOGS, "--robot", "nona"), 1
    ) == (
        f"Error: dataset '{LOGS}' holds trajectories of hexa, not nona; leave --robot out or "
        "give the dataset's robot"
    )
    assert error_line(invoke("run", "--model", "sdnn", "--dataset", "nowhere"), 1).startswith(
        "Error: dataset 'nowhere' is not in the cache; see `symbench list datasets`"
    )
    assert error_line(invoke("run", "--model", "sdnn"), 2) == (
        "Error: give --robot (its standard dataset) or --dataset"
    )
    # and verify replays it on the cached import
    verified = invoke("verify", path)
    assert verified.exit_code == 0, verified.output
    assert "values agree" in verified.stdout


def test_a_standard_dataset_named_with_dataset_runs_its_own_preset(home, tmp_path):
    out = tmp_path / "results"
    run_command(out, "--dataset", SMOKE)
    assert read_record(out / f"{key(SMOKE, 'smoke')}.json").training.config.max_steps == 30


def test_records_of_two_datasets_coexist_and_the_board_groups_by_dataset(home, tmp_path):
    out = tmp_path / "results"
    result = sweep_command(out, "--datasets", f"{SMOKE},{LOGS}", "--seeds", "0,1")
    assert result.exit_code == 0, result.output
    # each dataset's own preset: smoke for the standard one, small (the default) for the import
    presets = ((SMOKE, "smoke"), (LOGS, "small"))
    names = [f"{key(d, p, seed=s)}.json" for d, p in presets for s in (0, 1)]
    assert sorted(p.name for p in out.glob("*.json")) == sorted(names)  # both, side by side
    board = tmp_path / "board"
    made = invoke("leaderboard", "--results", out, "--out", board)
    assert made.exit_code == 0, made.output
    page = (board / "hexa.md").read_text()
    assert [line for line in page.splitlines() if line.startswith("#")] == [
        "# hexa",
        f"## Dataset {SMOKE}, preset smoke, converge protocol",
        "### iid",
        f"## Dataset {LOGS}, preset small, converge protocol",
        "### iid",
    ]
    summary = (board / "summary.md").read_text()
    assert [line.split(" | ")[0] for line in summary.splitlines() if " | iid | " in line] == [
        f"| {SMOKE}",
        f"| {LOGS}",
    ] * 2  # the RMSE and the normalized RMSE tables
    csv = (board / "leaderboard.csv").read_text().splitlines()
    header = "robot,dataset,preset,protocol,size,split,model,variant,backend,seeds,"
    assert csv[0].startswith(header)
    assert [row.split(",")[:3] for row in csv[1:]] == [
        ["hexa", SMOKE, "smoke"],
        ["hexa", LOGS, "small"],
    ]


def test_the_data_axis_of_a_sweep_is_robots_or_datasets(home, tmp_path):
    for args in (("--robots", "hexa", "--datasets", LOGS), ()):
        assert error_line(sweep_command(tmp_path, *args), 2) == (
            "Error: give --robots (their standard datasets) or --datasets, not both"
        )


def test_a_board_refuses_one_dataset_under_two_presets(make_record, tmp_path):
    from symbench.core.board.leaderboard import aggregate, load_records

    for seed, preset in enumerate(("smoke", "small")):
        record = make_record(seed=seed)
        record["dataset"]["preset"] = preset
        write_record(record, tmp_path / f"r{seed}.json")
    with pytest.raises(SymbenchError) as error:
        aggregate(load_records(tmp_path))
    assert str(error.value) == (
        f"records of dataset {SMOKE} were made with 2 presets (r0.json (smoke), r1.json "
        "(small)); aggregate records of one preset per dataset only"
    )


def test_a_board_never_mixes_training_protocols_in_one_table(make_record, tmp_path):
    """Records of the same runs under `paper` (the old records, read so) and `converge` get
    sections of their own, each ranked on its own, with steps and stop reasons shown."""
    from symbench.core.board.leaderboard import aggregate, load_records, markdown
    from symbench.core.board.summary import headline

    for seed in range(3):
        for model, rmse in (("sdnn", 0.1), ("ffnn", 0.2)):
            paper = make_record(model=model, seed=seed, rmse=rmse)
            write_record(paper, tmp_path / f"paper-{model}-{seed}.json")
            converge = make_record(model=model, seed=seed, rmse=rmse / 10)
            converge["training"]["config"] |= {
                "protocol": "converge",
                "max_steps": 30,
                "eval_every": 10,
                "patience": 2,
            }
            converge["training"] |= {"steps": 30, "best_step": 20, "stopped_by": "budget"}
            write_record(converge, tmp_path / f"converge-{model}-{seed}.json")
    table = aggregate(load_records(tmp_path))
    assert sorted(set(zip(table.protocol, table.model, table["rank"]))) == [
        ("converge", "ffnn", 2),
        ("converge", "sdnn", 1),
        ("paper", "ffnn", 2),
        ("paper", "sdnn", 1),
    ]
    page = markdown(table, "hexa")
    assert [line for line in page.splitlines() if line.startswith("## ")] == [
        f"## Dataset {SMOKE}, preset smoke, converge protocol",
        f"## Dataset {SMOKE}, preset smoke, paper protocol",
    ]
    converge_part, paper_part = page.split("paper protocol")
    assert "| 30.0 | budget 3 |" in converge_part and "epoch-cap 3" not in converge_part
    assert "| epoch-cap 3 |" in paper_part and "budget" not in paper_part
    summary = headline(table)
    assert summary.count("# Trained under the") == 2
    converge_summary, paper_summary = summary.split("# Trained under the paper protocol")
    assert "0.01" in converge_summary and "0.1 " not in converge_summary
    assert "0.01" not in paper_summary


def test_a_spec_whose_robot_is_not_the_datasets_is_refused_before_any_work(home, tmp_path):
    spec = RunSpec(model="sdnn", robot="magneto", dataset=LOGS, preset="smoke", output=tmp_path)
    with pytest.raises(SymbenchError, match=f"dataset '{LOGS}' holds trajectories of hexa"):
        run(spec)
    assert not list(tmp_path.iterdir())

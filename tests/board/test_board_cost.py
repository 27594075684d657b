"""summary.md says what the board cost: the records' wall times summed per dataset and model."""

from __future__ import annotations

from symbench.core.board.cost import cost_section
from symbench.core.board.leaderboard import load_records, write_leaderboard
from symbench.core.runs.results import write_record


def test_hours_add_up_by_part_and_by_model(tmp_path, make_record):
    results = tmp_path / "results"
    results.mkdir()
    timings = {
        "sdnn": {"dataset_s": 360.0, "training_s": 3240.0, "evaluation_s": 1800.0},
        "ffnn": {"training_s": 720.0, "retraining_s": 1800.0, "evaluation_s": 0.0},
    }
    for model, parts in timings.items():
        for seed in range(3):
            record = make_record(model=model, seed=seed)
            record["timings_s"] = parts
            write_record(record, results / f"{model}{seed}.json")
    lines = cost_section(load_records(results))
    header = "| dataset | runs | training | retraining | evaluation | total | ffnn | sdnn |"
    # sdnn: 3 x 1.5 h, ffnn: 3 x 0.7 h; training includes making the dataset
    row = "| hexa-climb-smoke-v7 | 6 | 3.60 | 1.50 | 1.50 | 6.60 | 2.10 | 4.50 |"
    assert header in lines and row in lines
    write_leaderboard(results, tmp_path / "board")
    summary = (tmp_path / "board" / "summary.md").read_text()
    assert summary.endswith("\n".join(lines))
    assert summary.index("# Leaderboard summary") < summary.index("# What this board cost")


def test_a_model_in_two_backends_has_a_column_for_each(tmp_path, make_record):
    for backend, seconds in (("torch", 3600.0), ("jax", 1800.0)):
        for seed in range(3):
            record = make_record(model="sdnn", backend=backend, seed=seed)
            record["timings_s"] = {"training_s": seconds}
            write_record(record, tmp_path / f"{backend}{seed}.json")
    lines = cost_section(load_records(tmp_path))
    header = "| dataset | runs | training | retraining | evaluation | total | "
    assert header + "sdnn (acc, jax) | sdnn (acc, torch) |" in lines
    assert "| hexa-climb-smoke-v7 | 6 | 4.50 | 0.00 | 0.00 | 4.50 | 1.50 | 3.00 |" in lines


def test_records_that_count_cpu_and_time_evaluators_get_their_own_table(tmp_path, make_record):
    parts = {"training_s": 1800.0, "evaluation_s": 1440.0, "cpu_s": 2160.0}
    by_evaluator = {"evaluation_s[closed-loop]": 1080.0, "evaluation_s[equivariance]": 360.0}
    for seed in range(2):
        record = make_record(model="sdnn", seed=seed)
        record["timings_s"] = {**parts, **by_evaluator}
        write_record(record, tmp_path / f"timed{seed}.json")
    old = make_record(model="ffnn", seed=0)  # made before runs counted CPU seconds
    old["timings_s"] = {"training_s": 3600.0}
    write_record(old, tmp_path / "old.json")
    lines = cost_section(load_records(tmp_path))
    assert "| dataset | runs | wall | CPU | evaluation | closed-loop | equivariance |" in lines
    # two runs: 2 x (0.5 + 0.4) h of wall time, 2 x 0.6 h of CPU, the old record left out
    assert "| hexa-climb-smoke-v7 | 2 | 1.80 | 1.20 | 0.80 | 0.60 | 0.20 |" in lines
    (tmp_path / "timed0.json").unlink()
    (tmp_path / "timed1.json").unlink()
    assert not any("CPU" in line for line in cost_section(load_records(tmp_path)))

"""Leaderboard aggregation: mean ± std over seeds, ranking, refusal to mix datasets."""

from __future__ import annotations

import json

import pytest

from symbench.core.board.leaderboard import aggregate, load_records, write_leaderboard
from symbench.core.board.series import asymmetry_series
from symbench.core.common.errors import SymbenchError
from symbench.core.runs.results import write_record


def write_runs(folder, make_record, runs):
    for i, kwargs in enumerate(runs):
        write_record(make_record(**kwargs), folder / f"r{i}.json")


def test_mean_std_and_rank(tmp_path, make_record):
    runs = [dict(model="sdnn", seed=s, rmse=r) for s, r in enumerate([0.1, 0.2, 0.3])]
    runs += [dict(model="ffnn", seed=s, rmse=r) for s, r in enumerate([1.0, 1.0, 1.3])]
    write_runs(tmp_path, make_record, runs)
    table = aggregate(load_records(tmp_path))
    assert list(table.model) == ["sdnn", "ffnn"]
    assert list(table["rank"]) == [1, 2]
    sdnn = table.iloc[0]
    assert sdnn.seeds == 3
    assert sdnn.rmse_Nm_mean == pytest.approx(0.2)
    assert sdnn.rmse_Nm_std == pytest.approx(0.1)
    assert sdnn.epochs_mean == 3  # shows when the stopping rule ended training early


def test_refuses_to_mix_dataset_versions(tmp_path, make_record):
    write_runs(tmp_path, make_record, [dict(seed=0), dict(seed=1, content_hash="ef" * 32)])
    with pytest.raises(SymbenchError, match="2 different datasets"):
        aggregate(load_records(tmp_path))


def test_refuses_duplicate_runs(tmp_path, make_record):
    write_runs(tmp_path, make_record, [dict(seed=0), dict(seed=0, rmse=0.3)])
    with pytest.raises(SymbenchError, match="two records for the same run"):
        aggregate(load_records(tmp_path))


def test_the_learning_rate_is_shown_and_never_averaged_over(tmp_path, make_record):
    """A robot tuned between two sweeps gives seeds of two rates: two configurations."""
    records = [make_record(seed=s) for s in range(3)]
    write_runs(tmp_path / "one", lambda **kw: kw["record"], [dict(record=r) for r in records])
    table = aggregate(load_records(tmp_path / "one"))
    assert list(table.learning_rate) == [5e-4]
    write_leaderboard(tmp_path / "one", tmp_path / "out")
    assert "| parameters | learning rate |" in (tmp_path / "out" / "hexa.md").read_text()
    records[2]["model"]["learning_rate"] = 1.5e-3
    write_runs(tmp_path / "two", lambda **kw: kw["record"], [dict(record=r) for r in records])
    two_rates = r"learning rates 0.0005, 0.0015 \(r0.json and r2.json\)"
    with pytest.raises(SymbenchError, match=two_rates):
        aggregate(load_records(tmp_path / "two"))


def test_tables_and_plot_regenerate_identically(tmp_path, make_record):
    runs = [
        dict(model=m, split=f"fraction-{f}", seed=s, rmse=r * (1 + s / 10) / f)
        for m, r in (("sdnn", 0.1), ("ffnn", 0.5))
        for f in (0.1, 0.5)
        for s in range(3)
    ]
    runs += [dict(robot="nona", model="sdnn", seed=s) for s in range(2)]
    write_runs(tmp_path / "records", make_record, runs)
    first = write_leaderboard(tmp_path / "records", tmp_path / "out")
    names = sorted(p.name for p in first)
    assert names == [
        "claims.md",
        "hexa-sample-efficiency.png",
        "hexa.md",
        "leaderboard.csv",
        "nona.md",
        "summary.md",
    ]
    before = {p.name: p.read_bytes() for p in first}
    second = write_leaderboard(tmp_path / "records", tmp_path / "out")
    assert {p.name: p.read_bytes() for p in second} == before
    nona = (tmp_path / "out" / "nona.md").read_text()
    assert "| 1 | sdnn | acc | torch | 2 (<3) |" in nona  # too few seeds is flagged


def test_empty_folder_is_a_clear_error(tmp_path):
    with pytest.raises(SymbenchError, match="no result records"):
        load_records(tmp_path)


def test_records_without_the_ranking_metric_are_named(tmp_path, make_record):
    record = make_record()
    record["metrics"] = {"equivariance": {"max_rel_error": 1e-7}}
    write_record(record, tmp_path / "r0.json")
    with pytest.raises(SymbenchError, match="without a torque-error RMSE.*r0.json"):
        aggregate(load_records(tmp_path))


def test_checkpoint_files_beside_the_records_are_not_read(tmp_path, make_record):
    write_runs(tmp_path, make_record, [dict(seed=s) for s in range(3)])
    (tmp_path / "checkpoints" / "x" / "best").mkdir(parents=True)
    (tmp_path / "checkpoints" / "x" / "best" / "model.json").write_text('{"format": "model"}')
    assert len(load_records(tmp_path)) == 3


def test_schema_1_records_are_still_shown(tmp_path, make_record, as_schema_1):
    (tmp_path / "records").mkdir()
    for s in range(3):
        (tmp_path / "records" / f"r{s}.json").write_text(
            json.dumps(as_schema_1(make_record(seed=s)))
        )
    write_leaderboard(tmp_path / "records", tmp_path / "out")
    assert "| 1 | sdnn | acc | torch | 3 |" in (tmp_path / "out" / "hexa.md").read_text()


def test_output_names_cannot_leave_the_output_folder(tmp_path, make_record, as_schema_1):
    """Even an unsealed schema-1 record, which no seal protects, cannot name a path."""
    records, out = tmp_path / "a" / "records", tmp_path / "a" / "out"
    records.mkdir(parents=True)
    for s in range(3):
        record = as_schema_1(make_record(seed=s))
        record["robot"] = "../../x"
        (records / f"r{s}.json").write_text(json.dumps(record))
    with pytest.raises(SymbenchError, match="robot: String should match pattern"):
        write_leaderboard(records, out)
    assert sorted(p.relative_to(tmp_path).as_posix() for p in tmp_path.rglob("*")) == [
        "a",
        "a/records",
        "a/records/r0.json",
        "a/records/r1.json",
        "a/records/r2.json",
    ]


def test_asymmetric_variants_are_plotted_against_their_asymmetry(tmp_path, make_record):
    """hexa and its variants hexa-asym-A: each model's RMSE per A, with the datasets' own
    torque asymmetry (data-symmetry evaluator) beside it; a robot without variants gets no
    such plot, and a split run on the symmetric robot only is left out of it."""
    runs = []
    for robot, asym, data in (("hexa", 0.0, 1e-13), ("hexa-asym-0.1", 0.1, 0.05)):
        for model, rmse in (("sdnn", 0.01), ("ffnn", 0.1)):
            for seed in range(3):
                record = make_record(robot=robot, model=model, seed=seed, rmse=rmse + asym)
                record["metrics"]["data-symmetry"] = {"tau_rel_error": data}
                runs.append(record)
    runs += [make_record(split="unseen-heading", seed=s) for s in range(3)]
    runs += [make_record(robot="nona", seed=s) for s in range(3)]
    for i, record in enumerate(runs):
        write_record(record, tmp_path / "records" / f"r{i}.json")
    names = sorted(p.name for p in write_leaderboard(tmp_path / "records", tmp_path / "out"))
    assert "hexa-asymmetry.png" in names and "nona-asymmetry.png" not in names
    table = aggregate(load_records(tmp_path / "records"))
    assert asymmetry_series(table, "nona") == ([], None)
    curves, data = asymmetry_series(table, "hexa")
    assert [c.label for c in curves] == ["ffnn (acc, torch, iid)", "sdnn (acc, torch, iid)"]
    sdnn = curves[1].points
    assert list(sdnn) == [0.0, 0.1]
    assert [s.mean for s in sdnn.values()] == pytest.approx([0.01, 0.11])
    assert [s.low for s in sdnn.values()] == [s.high for s in sdnn.values()]
    assert sdnn[0.1].seeds == pytest.approx((0.11, 0.11, 0.11))  # each seed's dot
    assert data == ([0.0, 0.1], pytest.approx([1e-13, 0.05]))

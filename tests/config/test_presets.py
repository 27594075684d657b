"""One Preset object per preset holds every size, budget and horizon; `symbench presets`
shows them, and the runner, the evaluators and the splits read their numbers from it."""

from __future__ import annotations

import dataclasses
import json
import re
from types import SimpleNamespace

import numpy as np
import pytest
from cli_invoke import error_line, invoke
from stand_ins import (
    closed_loop_dataset,
    tracked_to_the_end,
    trained_on_split,
    without_open_loop,
)

import symbench
from symbench.core.common.errors import SymbenchError, UnknownNameError
from symbench.core.config.cli import SECTIONS, _cell
from symbench.core.config.datasets import ClimbDistribution, ScenarioGrid
from symbench.core.config.presets import (
    GAIT_SPREAD,
    LEGACY_PRESETS,
    PRESETS,
    ClosedLoop,
    Evaluation,
    SampleEfficiency,
    Training,
    dataset_id,
    parse_dataset_id,
    preset,
)
from symbench.core.config.protocols import Converge, Cosine, Paper
from symbench.core.data import load_dataset
from symbench.core.plugin import registry
from symbench.core.runs.evaluation import EvaluationContext
from symbench.core.runs.run_config import check_names, train_config
from symbench.core.runs.spec import RunSpec
from symbench.plugins.evaluators import closed_loop, invariance, sample_efficiency
from symbench.plugins.splits import symbench_splits

# The published board was made with these numbers: changing one is a new protocol.
SMOKE_TRAINING = Training(max_steps=30, eval_every=10, patience=2, max_epochs=3)
SMALL_TRAINING = Training(max_steps=10000, eval_every=500, patience=6, max_epochs=60)
BUDGETS = {
    "smoke": {
        "training": SMOKE_TRAINING,
        "horizon_s": 1.0,
        "references": 2,
        "grid_seconds": 1.0,
        "push_n": 100.0,
    },
    "small": {
        "training": SMALL_TRAINING,
        "horizon_s": 2.0,
        "references": 32,
        "grid_seconds": 2.0,
        "push_n": 100.0,
    },
    "transfer": {
        "training": SMALL_TRAINING,
        "horizon_s": 2.0,
        "references": 6,
        "grid_seconds": 2.0,
    },
    "paper": {
        "training": Training(
            max_steps=200000, eval_every=5000, patience=4, max_epochs=500, val_stride=4
        ),
        "horizon_s": 10.0,
        "references": 8,
        "grid_seconds": 10.0,
    },
    "smoke-noisy": {
        "training": SMOKE_TRAINING,
        "horizon_s": 1.0,
        "references": 2,
        "grid_seconds": 1.0,
        "push_n": 100.0,
    },
    "small-noisy": {
        "training": SMALL_TRAINING,
        "horizon_s": 2.0,
        "references": 32,
        "grid_seconds": 2.0,
        "push_n": 100.0,
    },
}
# the closed loop trains on these presets' datasets (data for control)
TRAIN_PRESETS = {
    "smoke": "smoke-noisy",
    "small": "small-noisy",
    "transfer": None,
    "paper": None,
    "smoke-noisy": "smoke-noisy",
    "small-noisy": "small-noisy",
}
# What the dataset metadata stores (and so its content hash covers), in this order: a grid's
# (smoke; every preset up to dataset v6) and drawn climbs' (dataset v7)
DRAWN_KEYS = [
    "name",
    "description",
    "distribution",
    "climbs",
    "inclinations_deg",
    "leg_orders",
    "gait_spread",
    "seconds",
    "draw_seed",
]
GRID_KEYS = [
    "name",
    "description",
    "inclinations_deg",
    "headings_deg",
    "yaws_per_turn",
    "directions",
    "leg_orders",
    "seeds",
    "seconds",
    "yaws_deg",
]


def with_preset(monkeypatch, name: str, **groups) -> None:
    """Replace groups (training=..., closed_loop=...) of a preset for one test."""
    monkeypatch.setitem(PRESETS, name, dataclasses.replace(PRESETS[name], **groups))


def test_the_budgets_are_those_of_the_published_board():
    assert list(PRESETS) == list(BUDGETS)
    for name, budget in BUDGETS.items():
        p = PRESETS[name]
        assert p.training == budget["training"]
        assert p.closed_loop == ClosedLoop(
            seconds=budget["horizon_s"],
            references=budget["references"],
            pd_fractions=(0.0, 0.1, 0.3, 1.0),
            headline_pd=0.1,
            train_preset=TRAIN_PRESETS[name],
            push_n=budget.get("push_n", 0.0),
            push_s=0.1,
        )
        assert p.closed_loop.seconds == p.dataset.seconds  # the horizon: a whole climb
        assert p.dataset.seconds == budget["grid_seconds"]
        assert p.evaluation == Evaluation(max_samples=4096, invariance_trials=4)
        assert p.sample_efficiency == SampleEfficiency(fractions=(0.1, 0.25, 0.5, 0.75))


def test_the_v6_closed_loop_is_the_published_v6_boards():
    """v6 records keep meaning what they meant: 6 unpushed references (8 on paper) over
    2.6 s climbs (10 s), trained on v6's own noisy data where there is one."""
    v6 = {
        "smoke@v6": (1.0, 2, "smoke-noisy@v6"),
        "small@v6": (2.6, 6, "small-noisy@v6"),
        "transfer@v6": (2.6, 6, None),
        "paper@v6": (10.0, 8, None),
        "smoke-noisy@v6": (1.0, 2, "smoke-noisy@v6"),
        "small-noisy@v6": (2.6, 6, "small-noisy@v6"),
    }
    assert list(LEGACY_PRESETS) == list(v6)
    for name, (seconds, references, train) in v6.items():
        loop = LEGACY_PRESETS[name].closed_loop
        assert loop == ClosedLoop(seconds, references, (0.0, 0.1, 0.3, 1.0), 0.1, train)
        assert loop.push_n == 0.0


def test_the_stored_grid_holds_the_grid_and_no_budget():
    for p in [*PRESETS.values(), *LEGACY_PRESETS.values()]:
        grid = p.grid(3)
        noisy = ["torque_noise"] if p.dataset.torque_noise else []  # only when there is noise
        assert (grid["name"], grid["description"]) == (p.name, p.description)
        if isinstance(p.dataset, ClimbDistribution):
            assert list(grid) == [*DRAWN_KEYS, *noisy]
            continue
        spread = ["gait_spread"] if p.dataset.gait_spread else []  # v7's smoke only
        assert list(grid) == [*GRID_KEYS[:-1], *noisy, *spread, GRID_KEYS[-1]]
        assert grid["yaws_deg"] == list(p.dataset.yaws_deg(3))
    assert preset("small@v6").grid(6)["yaws_deg"] == [15.0 * k for k in range(24)]
    assert preset("small@v6").grid(9)["yaws_deg"] == [10.0 * k for k in range(36)]
    assert PRESETS["smoke"].grid(9)["yaws_deg"] == [0.0, 180.0, 250.0]


def test_earlier_versions_keep_their_ids_and_grids():
    """v6's datasets (the published v6 board's) stay standard: `small@v6` names them."""
    assert dataset_id("hexa", "small") == "hexa-climb-small-v7"
    assert dataset_id("hexa", "small@v6") == "hexa-climb-small-v6"
    assert parse_dataset_id("hexa-climb-small-v6") == ("hexa", "small@v6")
    assert parse_dataset_id("hexa-climb-small-noisy-v6") == ("hexa", "small-noisy@v6")
    assert parse_dataset_id("hexa-climb-small-v7") == ("hexa", "small")
    assert parse_dataset_id("hexa-climb-small-v5") is None
    assert preset("small@v6").closed_loop.train_preset == "small-noisy@v6"
    assert preset("small@v6").name == "small" and preset("small@v6").version == 6
    grid = preset("small@v6").dataset
    assert isinstance(grid, ScenarioGrid) and grid.seconds == 2.6 and not grid.gait_spread


@pytest.mark.parametrize("name", ["small", "transfer", "paper"])
def test_drawn_climbs_differ_and_their_distribution_keeps_the_symmetry(name):
    """Every start is drawn from a distribution the rotations and mirrors map onto itself
    (the full circle; the band of slopes), the same on every call, and no two climbs share
    their draws: none is an image of another."""
    p = PRESETS[name]
    assert isinstance(p.dataset, ClimbDistribution)
    climbs = p.scenarios("hexa", 6, 6)
    assert climbs == p.scenarios("hexa", 6, 6) and len(climbs) == p.dataset.climbs
    low, high = p.dataset.inclinations_deg
    yaws = np.array([c.yaw_deg for c in climbs])
    directions = np.array([c.direction for c in climbs], dtype=float)
    assert all(low <= c.inclination_deg <= high for c in climbs)
    assert yaws.min() >= 0 and yaws.max() < 360 and 0 <= directions.min() < directions.max() < 360
    sectors = np.bincount((yaws // 60).astype(int), minlength=6)  # every sector drawn alike
    assert sectors.min() > 0.5 * len(climbs) / 6
    assert len({(c.yaw_deg % 60, c.heading_deg, c.direction) for c in climbs}) == len(climbs)
    assert len({c.seed for c in climbs}) == len(climbs)  # each steps with its own draws
    assert all(c.gait_spread == GAIT_SPREAD for c in climbs)


def test_presets_json_is_every_preset_with_every_number():
    result = invoke("presets", "--json")
    assert result.exit_code == 0, result.output
    shown = json.loads(result.stdout)
    assert list(shown) == list(PRESETS)
    for name, p in PRESETS.items():
        assert shown[name] == json.loads(json.dumps(dataclasses.asdict(p)))
        assert list(shown[name]) == ["name", "description", *SECTIONS]
        assert shown[name]["version"] == 7
    assert shown["paper"]["training"] == {
        "max_steps": 200000,
        "eval_every": 5000,
        "patience": 4,
        "max_epochs": 500,
        "val_stride": 4,
    }
    assert shown["smoke"]["closed_loop"] == {
        "seconds": 1.0,
        "references": 2,
        "pd_fractions": [0.0, 0.1, 0.3, 1.0],
        "headline_pd": 0.1,
        "train_preset": "smoke-noisy",
        "push_n": 100.0,
        "push_s": 0.1,
    }
    assert shown["small"]["sample_efficiency"] == {"fractions": [0.1, 0.25, 0.5, 0.75]}
    assert shown["paper"]["dataset"]["inclinations_deg"] == [45.0, 135.0]


def test_presets_table_has_a_row_per_number(monkeypatch):
    monkeypatch.setenv("COLUMNS", "400")  # no wrapped cells
    result = invoke("presets")
    assert result.exit_code == 0, result.output
    lines = result.stdout.splitlines()
    (header,) = [line for line in lines if line.startswith("┃ section")]
    assert all(name in header for name in PRESETS)
    doc = {name: json.loads(json.dumps(dataclasses.asdict(p))) for name, p in PRESETS.items()}
    for section in SECTIONS:
        values = [p[section] for p in doc.values()]
        if not isinstance(values[0], dict):
            cells = [section.replace("_", " "), *map(_cell, values)]
            row = re.compile(r"│\s*" + r"\s*│\s*│?\s*".join(map(re.escape, cells)) + r"\s*│")
            assert any(row.search(line) for line in lines), (section, cells)
            continue
        for setting in dict.fromkeys(s for v in values for s in v):
            cells = [_cell(v.get(setting, "")) for v in values]
            row = re.compile(r"│\s*" + r"\s*│\s*".join(map(re.escape, [setting, *cells])) + r"\s*│")
            assert any(row.search(line) for line in lines), (section, setting, cells)
    assert "45, 135" in result.stdout and "default, reversed" in result.stdout
    assert "small-noisy" in header


def test_a_wrong_presets_command_line_is_one_line():
    assert "unexpected extra argument" in error_line(invoke("presets", "small"), 2)


def test_the_run_takes_its_budgets_from_the_preset(monkeypatch):
    spec = RunSpec(model="sdnn", robot="hexa", preset="smoke", progress=False)
    config = train_config(spec)
    assert config.schedule == Converge(max_steps=30, eval_every=10, patience=2)
    assert config.unused == Paper(max_epochs=3)  # kept in the record's flat layout, unused
    with_preset(monkeypatch, "smoke", training=Training(700, 70, 3, max_epochs=7))
    config = train_config(spec)
    assert config.schedule == Converge(700, 70, 3)
    assert config.val_stride == 1
    with_preset(monkeypatch, "smoke", training=Training(700, 70, 3, max_epochs=7, val_stride=4))
    assert train_config(spec).val_stride == 4
    longer = train_config(dataclasses.replace(spec, max_steps=140))  # --max-steps
    assert longer.schedule == Converge(140, 70, 3)
    paper = dataclasses.replace(spec, protocol="paper")
    assert train_config(paper).schedule == Paper(max_epochs=7)
    assert train_config(paper).unused == Converge(700, 70, 3)
    shorter = train_config(dataclasses.replace(paper, max_epochs=2))  # --max-epochs
    assert shorter.schedule == Paper(max_epochs=2)
    assert train_config(dataclasses.replace(spec, protocol="cosine")).schedule == Cosine(700, 70, 3)


@pytest.mark.parametrize(
    "protocol, budget, option",
    [
        ("converge", {"max_epochs": 2}, "--max-epochs"),
        ("cosine", {"max_epochs": 2}, "--max-epochs"),
        ("paper", {"max_steps": 9}, "--max-steps"),
    ],
)
def test_a_budget_of_another_protocol_is_refused(protocol, budget, option):
    spec = RunSpec(model="sdnn", robot="hexa", preset="smoke", protocol=protocol, **budget)
    with pytest.raises(SymbenchError, match=f"{option} is a budget of another protocol"):
        train_config(spec)


def test_an_unknown_preset_is_named_with_the_known_ones():
    with pytest.raises(UnknownNameError, match=r"unknown preset 'smal'; did you mean small"):
        check_names(RunSpec(model="sdnn", robot="hexa", preset="smal"))


def _context(preset, dataset, retrain=None, test_trajectories=(), predict=None):
    entry = SimpleNamespace(name="m", backend="torch", view="leg_grouped", variant="acc")
    return EvaluationContext(
        entry=entry,
        dataset=dataset,
        preset=preset,
        split="unseen-rotation",  # not iid: sample efficiency retrains on iid
        seed=0,
        predict=predict,
        test=None,
        test_trajectories=np.asarray(test_trajectories),
        output_dir=None,
        retrain=retrain,
    )


@pytest.mark.parametrize("references", [1, 3])
def test_closed_loop_tracks_the_presets_references_over_its_horizon(
    monkeypatch, tmp_path, references
):
    simulated, tracked = [], []

    def simulate(scenario, record_period, push=None):
        assert record_period == 0.001  # every physics step
        assert push is None  # the budget below pushes not
        simulated.append(scenario)
        steps = int(round(scenario.seconds / 0.001))
        arrays = {"t": 0.001 * np.arange(steps), "tau": np.zeros((steps, 6, 3))}
        return SimpleNamespace(attached=True, arrays=arrays)

    def track(scenario, reference, policy, pd, observe=None, push=None):
        tracked.append(pd)
        return tracked_to_the_end(scenario)

    def track_batch(jobs, policy):  # the model's rollouts, in the order of its jobs
        return [track(job.scenario, job.reference, policy, job.pd_gains) for job in jobs]

    # where the closed loop's one implementation (`ClosedLoopSetup`) finds them
    monkeypatch.setattr("symbench.core.sim.climb.rollout.simulate", simulate)
    monkeypatch.setattr("symbench.core.runs.closed_loop.track", track)
    monkeypatch.setattr("symbench.core.runs.closed_loop.track_batch", track_batch)
    without_open_loop(monkeypatch)
    budget = ClosedLoop(
        seconds=0.05, references=references, pd_fractions=(0.0, 0.5), headline_pd=0.5
    )
    preset = dataclasses.replace(PRESETS["small"], closed_loop=budget)
    dataset = closed_loop_dataset([{"robot": "hexa", "yaw_deg": 10.0 * i} for i in range(4)])
    context = _context(preset, dataset, retrain=trained_on_split, test_trajectories=[3, 2, 1, 0])
    context.output_dir = tmp_path
    metrics = closed_loop.evaluate(context)
    assert metrics["horizon_s"] == pytest.approx(0.05) and metrics["references"] == references
    assert metrics["pd_fractions"] == [0.0, 0.5] and metrics["pd_gains"] == [10.0, 1.5]
    assert [s.seconds for s in simulated] == [0.05] * references
    assert [s.yaw_deg for s in simulated] == [0.0, 10.0, 20.0][:references]  # in id order
    # per reference the oracle once (at the headline fraction) and the floor at every
    # fraction, then the model at every fraction for every reference
    calibration = [(10.0, 1.5), (0.0, 0.0), (10.0, 1.5)] * references
    assert tracked == calibration + [(0.0, 0.0), (10.0, 1.5)] * references
    # the calibration is kept: a second evaluation tracks the model only
    simulated.clear()
    tracked.clear()
    assert closed_loop.evaluate(context) == metrics
    assert simulated == [] and tracked == [(0.0, 0.0), (10.0, 1.5)] * references


def test_sample_efficiency_trains_on_the_presets_fractions(monkeypatch, tmp_path):
    asked = []

    def retrain(split, variant):
        asked.append(split)
        return trained_on_split(split, variant)

    monkeypatch.setattr(symbench, "sample_efficiency_png", lambda *args: None)
    dataset = SimpleNamespace(spec=SimpleNamespace(name="hexa"), id="hexa-climb-small-v6")
    context = _context(PRESETS["small"], dataset, retrain=retrain)
    context.output_dir = tmp_path
    metrics = sample_efficiency.evaluate(context)
    curve = metrics["rmse_by_fraction"]
    e = context.entry  # the plot is named like the run's record: no run overwrites another's
    assert metrics["plot"] == str(
        tmp_path
        / f"hexa-climb-small-v6__small__{e.name}__{e.variant}__{e.backend}__seed{context.seed}"
        "-sample-efficiency.png"
    )
    assert list(curve) == ["0.1", "0.25", "0.5", "0.75", "1.0"]  # the published metric keys
    assert asked == ["fraction-0.1", "fraction-0.25", "fraction-0.5", "fraction-0.75", "iid"]
    asked.clear()
    context = _context(
        dataclasses.replace(PRESETS["small"], sample_efficiency=SampleEfficiency((0.5,))),
        dataset,
        retrain=retrain,
    )
    context.output_dir = tmp_path
    assert list(sample_efficiency.evaluate(context)["rmse_by_fraction"]) == ["0.5", "1.0"]
    assert asked == ["fraction-0.5", "iid"]


def test_transform_evaluators_spend_the_presets_evaluation_budget(smoke_hexa):
    dataset = load_dataset(smoke_hexa.dataset_id)
    evaluation = Evaluation(max_samples=5, invariance_trials=2)
    preset = dataclasses.replace(PRESETS["smoke"], evaluation=evaluation)
    context = _context(
        preset,
        dataset,
        test_trajectories=dataset.trajectory_ids,
        predict=lambda inputs: np.zeros((len(next(iter(inputs.values()))), 6, 3)),
    )
    raw, ids = context.test_raw()
    assert len(ids) == 5 and all(len(v) == 5 for v in raw.values())
    assert len(invariance.evaluate(context)["trials"]) == 2


def _fraction_splits(names) -> list[str]:
    return sorted(n for n in names if n.startswith("fraction-"))


def test_the_fraction_splits_are_the_presets_fractions(monkeypatch):
    fractions = {f for p in PRESETS.values() for f in p.sample_efficiency.fractions}
    expected = sorted(f"fraction-{f:g}" for f in fractions)
    assert _fraction_splits(registry.collect("splits")) == expected
    assert expected == ["fraction-0.1", "fraction-0.25", "fraction-0.5", "fraction-0.75"]
    with_preset(monkeypatch, "paper", sample_efficiency=SampleEfficiency((0.3, 0.5)))
    registered = _fraction_splits(e.name for e in symbench_splits())
    assert registered == sorted([*expected, "fraction-0.3"])


def test_presets_read_at_80_columns(monkeypatch):
    """Before: seven presets squeezed side by side into 80 columns, every value wrapped into
    a column of one word ("transfe" over "r", "one-sec" over "ond"); then, three presets per
    table, their descriptions still wrapped in a column a dozen characters wide, breaking
    words ("unseen-incli" over "nation")."""
    monkeypatch.setenv("COLUMNS", "80")
    result = invoke("presets")
    assert result.exit_code == 0, result.output
    lines = result.stdout.splitlines()
    assert max(map(len, lines)) <= 80
    headers = [line.split("┃") for line in lines if line.startswith("┃ section")]
    assert [h.strip() for cells in headers for h in cells[3:-1]] == list(PRESETS)
    words = " ".join(result.stdout.split())
    for name, p in PRESETS.items():  # each description whole, after its name
        assert f"{name} {p.description}" in words
    doc = {name: json.loads(json.dumps(dataclasses.asdict(p))) for name, p in PRESETS.items()}
    cells = {s.replace("_", " ") for s in SECTIONS}
    for p in doc.values():
        for section in SECTIONS:
            found = p[section].items() if isinstance(p[section], dict) else [("", p[section])]
            cells |= {setting for setting, _ in found} | {_cell(v) for _, v in found}
    known = {word for cell in cells for word in cell.split()}
    body = [line for line in lines if line.startswith("│")]
    shown = {word for line in body for cell in line.split("│") for word in cell.split()}
    assert shown <= known, shown - known  # no word of a table broken across lines

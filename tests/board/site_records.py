"""The records of the site's tests, written as runs write them (`write_record` seals them),
and read back as plain JSON to know what the pages must show.

hexa's smoke dataset (converge protocol): three models on iid, an unseen split and a
fraction, three seeds each, closed-loop metrics on iid. The NRMSE ranks the models the other
way round from the RMSE, so that sorting by it changes the order. ffnn trained on twice the
preset's budget (its command says so), gnn with a hyper-parameter override (its command
sets it with --size). sdnn alone claims equivariance, as in the zoo.
Beside them on hexa: a schema-1 model (unsealed; the paper protocol). On nona: one model on
iid only, so that its page has no plot.
"""

from __future__ import annotations

import hashlib
import json
from collections.abc import Callable
from pathlib import Path

from symbench.core.config.presets import dataset_id
from symbench.core.runs.results import write_record

MODELS = {"sdnn": (0.10, 0.30), "gnn": (0.25, 0.20), "ffnn": (0.40, 0.10)}  # RMSE, NRMSE
SPLITS = {"iid": 1.0, "unseen-heading": 2.0, "fraction-0.5": 1.5}  # the RMSE's factor
SEEDS = (0, 1, 2)
CLOSED_LOOP_SCORE = {"sdnn": 0.8, "gnn": 0.5, "ffnn": 0.2}
LEGACY_MODEL = "mlp-legacy"
HEXA = dataset_id("hexa", "smoke")
NONA = dataset_id("nona", "smoke")


def converge_record(make_record: Callable[..., dict], model: str, split: str, seed: int) -> dict:
    rmse, nrmse = MODELS[model]
    record = make_record(model=model, split=split, seed=seed, rmse=rmse * SPLITS[split])
    record["metrics"]["torque-error"]["rmse"] += seed / 1000
    record["model"]["equivariant"] = model == "sdnn"  # as the zoo: sdnn is, gnn and ffnn not
    record["metrics"]["torque-error"]["nrmse"] = nrmse * SPLITS[split] + seed / 1000
    record["training"]["config"].update(
        protocol="converge",
        max_steps=60 if model == "ffnn" else 30,
        eval_every=10,
        patience=2,
        hyper={"latent": 64} if model == "gnn" else {},
    )
    steps = 20 + 10 * seed
    record["training"].update(
        steps=steps, best_step=steps - 10, stopped_by="patience", stop_reason="2 checks"
    )
    checkpoint = hashlib.sha256(f"{model} {split} {seed}".encode()).hexdigest()
    record["training"]["checkpoint_sha256"] = {"model.safetensors": checkpoint}
    if split == "iid":
        score = CLOSED_LOOP_SCORE[model] + seed / 20
        record["metrics"]["closed-loop"] = {
            "pd_normalized_score": score,
            "pd_time_to_failure_s": 2 * score,
            "pd_success_rate": 0.5,
            "pd_joint_rmse_rad": 0.02,
        }
    return record


def write_results(folder: Path, make_record: Callable[..., dict], as_schema_1) -> Path:
    """The records described above, in `folder`."""
    folder.mkdir()
    for model in MODELS:
        for split in SPLITS:
            for seed in SEEDS:
                record = converge_record(make_record, model, split, seed)
                write_record(record, folder / f"{model}-{split}-seed{seed}.json")
    for seed in SEEDS:
        legacy = as_schema_1(make_record(model=LEGACY_MODEL, seed=seed, rmse=0.3 + seed / 100))
        (folder / f"{LEGACY_MODEL}-seed{seed}.json").write_text(json.dumps(legacy))
        nona = make_record(robot="nona", seed=seed, rmse=0.2 + seed / 100)
        write_record(nona, folder / f"nona-sdnn-seed{seed}.json")
    return folder


def table_id(protocol: str, split: str) -> str:
    """The id of a split's table on a board page (a CSS selector too: no '.')."""
    return f"{protocol}--{split.replace('.', '-')}"


def runs_of(folder: Path, dataset: str, protocol: str, split: str, model: str) -> list[dict]:
    """The records of one model group, as JSON, by seed."""
    runs = [json.loads(p.read_text()) for p in sorted(folder.glob("*.json"))]
    return sorted(
        (
            r
            for r in runs
            if (r["dataset"]["id"], r["split"], r["model"]["name"]) == (dataset, split, model)
            and r["training"].get("config", {}).get("protocol", "paper") == protocol
        ),
        key=lambda r: r["seed"],
    )


def metric(runs: list[dict], evaluator: str, name: str) -> list[float]:
    return [r["metrics"][evaluator][name] for r in runs]

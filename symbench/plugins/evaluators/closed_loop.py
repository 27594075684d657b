"""The trained model as the climbing robot's feedforward controller, in simulation.

Protocol (`symbench presets` shows its numbers, the preset's `closed_loop` group):

- References: up to `references` held-out test climbs of the run's split, from distinct
  symmetry orbits, chosen deterministically (`held_out_scenarios`), so every model of a
  split and seed tracks the same ones. The expert (the whole-body controller) climbs each
  again, recorded at every physics step; its rows every 6 ms are the dataset's. The
  horizon is the held-out climb's own length (the trajectories the model was trained on
  are as long), capped at the preset's `seconds`.
- Training data (`trained_on` in the metrics): the model is retrained on the `next` variant
  of the run's split, by default on the noisy variant of a standard dataset (the preset's
  `closed_loop.train_preset`, e.g. small -> small-noisy: the expert's executed torques
  perturbed, its commands at the perturbed states as labels, as in DART), so that it has
  seen states off the expert's path and the corrections the expert made there; never on
  the run's test climbs. An imported dataset has no noisy variant: the run's own is used.
  The references are the expert's noise-free climbs.
- Control: the model, trained on the `next` variant, gives the feedforward torque at every
  physics step; a joint PD at a fraction of the robot's servo gains (Kp, Kd) about the
  reference at the current time closes the loop (`symbench.track` says exactly what is
  actuated). Every fraction of `pd_fractions` is run and reported.
- Calibration rows, with the same references and PD: `oracle` (the expert's recorded
  feedforward, replayed: it reproduces the expert's climb to rounding), `floor` (zero
  feedforward: the PD alone) and `expert` (the live whole-body controller, which made the
  reference). `normalized_score` places the model between floor (0) and oracle (1) on the
  time held, so models compare across robots; `normalized_rmse_score` does the same with
  the joint tracking RMSE (the score at fractions where all three hold the horizon).
- Cost: only the model rows depend on the model. References, expert success, oracle (one
  replay, at the headline fraction: it is the same at every fraction) and floor are kept
  under the output folder (`closed-loop-cache/<key>/`, keyed by dataset content, robot,
  references and fractions), so the models of a sweep measure them once. The model's
  rollouts, every reference at every fraction, run in lockstep (`track_batch`): one model
  call per physics step for all of them. Its model is declared (`trainings`), so a run with
  two workers trains it beside the run's own.
- Metrics per row and fraction: success rate (held the whole horizon: no fall, no stance
  foot lost, base within half a step of the reference's), time to failure, joint tracking
  RMSE (over the time held), base pose drift (position and orientation error at the last
  step held).

Headline (`success_rate`, `time_to_failure_s`, ... without prefix: the model alone, PD
fraction 0; `pd_*`: the headline fraction, the preset's `headline_pd`). The headline
fraction is 0.1: with it the PD alone (the floor) loses the path within a fraction of the
horizon while the oracle holds it, so the feedforward must carry the climb (gravity, the
magnets' reactions, the swing) and the score measures the model; at 1.0 the servo gains
alone track a climb (the floor holds), at 0 the unstable gait turns any torque error into a
fall within about a second, which measures little but the model's bias.
"""

from __future__ import annotations

import hashlib
import json
import math
import os
import tempfile
from pathlib import Path
from types import SimpleNamespace

import numpy as np

from symbench import EvaluationContext, reference_scenarios
from symbench import held_out_scenarios as held_out_scenarios  # kept importable from here

NAME = "closed-loop"
DESCRIPTION = (
    "learned model as the feedforward controller tracking held-out climbs from distinct "
    "symmetry orbits, with joint PD at fractions of the servo gains; oracle, floor and "
    "expert rows calibrate it"
)
ROWS = ("model", "oracle", "floor")


def trainings(context: EvaluationContext) -> list[tuple[str | None, str, str]]:
    """The model it tracks with: the `next` variant on the data for control, for a run to
    train ahead."""
    return [(context.control_dataset(), context.split, "next")]


def evaluate(context: EvaluationContext) -> dict:
    from symbench import feedforward_policy, model_jobs, track_batch

    trained_on = context.control_dataset()  # the noisy variant of a standard dataset
    trained = context.on_dataset(trained_on, context.split, "next")
    policy = feedforward_policy(trained.predict, context.dataset.frames, context.entry.view)
    budget = context.preset.closed_loop
    control = context.robot.control
    fractions = tuple(float(f) for f in budget.pd_fractions)
    scenarios = reference_scenarios(
        context.dataset,
        context.test_trajectories,
        budget.references,
        budget.seconds,
        context.robot.group.rotation_order,
    )
    measured = _calibration(context, scenarios, fractions, float(budget.headline_pd))
    # None: the expert itself fell, no reference to track
    kept = [(f, m) for f, m in zip(scenarios, measured, strict=True) if m is not None]
    calibration = [m for _, m in kept]
    # every reference at every fraction in lockstep: one model call per physics step
    references = [(scenario, ref) for scenario, ref, _, _ in calibration]
    jobs = model_jobs(references, fractions, (control.kp, control.kd))
    tracked = iter(track_batch(jobs, policy))
    runs: dict[str, dict[float, list]] = {row: {f: [] for f in fractions} for row in ROWS}
    for _, _, oracle, floor in calibration:
        for f in fractions:  # the order of model_jobs
            runs["model"][f].append(next(tracked))
            runs["oracle"][f].append(oracle)
            runs["floor"][f].append(floor[f])
    tried = len(scenarios)
    horizons = [float(fields["seconds"]) for fields, _ in kept]
    orbits = [_describe(fields) for fields, _ in kept]
    headline = float(budget.headline_pd)
    out: dict = {
        "trained_on": trained_on,
        "references": len(horizons),
        "orbits": orbits,
        "horizon_s": _mean(horizons),
        "pd_fractions": list(fractions),
        "headline_pd_fraction": headline,
        "pd_gains": [headline * control.kp, headline * control.kd],
        "expert_success_rate": len(horizons) / tried if tried else None,
    }
    by_fraction: dict[str, dict] = {}
    for f in fractions:
        rows = {row: _summary(runs[row][f]) for row in ROWS}
        by_fraction[str(f)] = {
            **rows,
            "normalized_score": _normalized(rows, horizons),
            "normalized_rmse_score": _normalized_rmse(rows),
        }
    out["by_pd_fraction"] = by_fraction
    for prefix, f in (("", fractions[0]), ("pd_", headline)):
        part = by_fraction[str(f)]
        out.update({prefix + k: v for k, v in part["model"].items()})
        out[prefix + "normalized_score"] = part["normalized_score"]
        out[prefix + "normalized_rmse_score"] = part["normalized_rmse_score"]
        for row in ("oracle", "floor"):
            out.update({f"{prefix}{row}_{k}": v for k, v in part[row].items() if k != "failures"})
    return out


CACHE_DIR = "closed-loop-cache"  # under the run's output folder
CACHE_VERSION = 1  # bump when what is cached, or how it is measured, changes


def _calibration(
    context: EvaluationContext,
    scenarios: list[dict],
    fractions: tuple[float, ...],
    oracle_pd: float,
) -> list:
    """Per reference scenario: None when the expert fell, else (scenario, reference, oracle,
    floor by fraction). None of it depends on the model, so it is measured once per
    (dataset content, robot, references, fractions) and kept under the output folder: a
    sweep pays it once. The oracle runs once, at `oracle_pd`: on the reference the PD and
    the residual vanish, so the applied torque is the recorded one at every fraction (the
    tests pin the replay at each)."""
    from symbench import Scenario, __version__, oracle_policy, simulate

    control = context.robot.control
    key = {
        "cache_version": CACHE_VERSION,
        "symbench": __version__,
        "dataset_content_hash": context.dataset.content_hash,
        "robot_spec_hash": context.robot.spec_hash(),
        "scenarios": scenarios,
        "pd_fractions": list(fractions),
        "oracle_pd_fraction": oracle_pd,
        "servo_gains": [control.kp, control.kd],
    }
    text = json.dumps(key, sort_keys=True, separators=(",", ":"))
    folder = Path(context.output_dir) / CACHE_DIR / hashlib.sha256(text.encode()).hexdigest()[:20]
    cached = _read_calibration(folder, key, fractions)
    if cached is not None:
        return cached
    from symbench import track

    out: list = []
    for fields in scenarios:
        scenario = Scenario.from_dict(fields)
        # the expert's climb recorded at every physics step: what `track` needs
        reference = simulate(scenario, record_period=control.timestep)
        if not reference.attached:
            out.append(None)
            continue
        ref = reference.arrays

        def floor(rows: dict[str, np.ndarray], ref=ref) -> np.ndarray:
            return np.zeros_like(ref["tau"][0])

        def gains(f: float) -> tuple[float, float]:
            return f * control.kp, f * control.kd

        replay = track(scenario, ref, oracle_policy(ref), gains(oracle_pd))
        floors = {f: track(scenario, ref, floor, gains(f)) for f in fractions}
        out.append((scenario, ref, replay, floors))
    _write_calibration(folder, key, out)
    return out


def _write_atomic(path: Path, write) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".tmp")
    try:
        with os.fdopen(fd, "wb") as handle:
            write(handle)
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise


def _write_calibration(folder: Path, key: dict, measured: list) -> None:
    """References as .npz (exact float64), then calibration.json last: its presence means
    the folder is complete."""
    rows: list = []
    for i, item in enumerate(measured):
        if item is None:
            rows.append(None)
            continue
        _, ref, oracle, floors = item
        _write_atomic(folder / f"reference-{i}.npz", lambda h, ref=ref: np.savez(h, **ref))
        rows.append(
            {
                "oracle": dict(vars(oracle)),
                "floor": [[f, dict(vars(r))] for f, r in floors.items()],
            }
        )
    body = json.dumps({"key": key, "references": rows}, indent=1).encode()
    _write_atomic(folder / "calibration.json", lambda h: h.write(body))


def _read_calibration(folder: Path, key: dict, fractions: tuple[float, ...]) -> list | None:
    """The cached calibration when it is complete and of this very key, else None."""
    from symbench import Scenario

    try:
        data = json.loads((folder / "calibration.json").read_text())
        if data["key"] != json.loads(json.dumps(key)):
            return None
        out: list = []
        for i, (fields, row) in enumerate(zip(key["scenarios"], data["references"], strict=True)):
            if row is None:
                out.append(None)
                continue
            with np.load(folder / f"reference-{i}.npz", allow_pickle=False) as npz:
                ref = {k: npz[k] for k in npz.files}
            floors = {float(f): SimpleNamespace(**r) for f, r in row["floor"]}
            if tuple(floors) != fractions:
                return None
            out.append((Scenario.from_dict(fields), ref, SimpleNamespace(**row["oracle"]), floors))
        return out
    except (OSError, ValueError, KeyError, TypeError):
        return None


def _describe(fields: dict) -> str:
    keys = ("inclination_deg", "heading_deg", "yaw_deg", "direction")
    return ", ".join(f"{k}={fields[k]}" for k in keys if k in fields)


def _mean(values: list[float]) -> float | None:
    """The mean, or None (JSON null: records hold no NaN) when there is nothing to average."""
    values = [v for v in values if not math.isnan(v)]
    return float(np.mean(values)) if values else None


def _summary(results: list) -> dict:
    return {
        "success_rate": _mean([float(r.attached) for r in results]),
        "time_to_failure_s": _mean([r.time_to_failure_s for r in results]),
        "joint_rmse_rad": _mean([r.joint_rmse_rad for r in results]),
        "base_drift_m": _mean([r.base_drift_m for r in results]),
        "base_drift_deg": _mean([r.base_drift_deg for r in results]),
        "failures": [r.failure for r in results if r.failure],
    }


def _normalized(rows: dict[str, dict], horizons: list[float]) -> float | None:
    """The model's share of the horizon held, 0 at the floor's and 1 at the oracle's (None
    where the two hold alike: the PD alone then tracks, and the fraction ranks nothing)."""
    held = {row: rows[row]["time_to_failure_s"] for row in ROWS}
    if not horizons or any(v is None for v in held.values()):
        return None
    span = held["oracle"] - held["floor"]
    if not span > 1e-9 * max(horizons):
        return None
    return float((held["model"] - held["floor"]) / span)


def _normalized_rmse(rows: dict[str, dict]) -> float | None:
    """The model's joint tracking RMSE placed between the floor's (0) and the oracle's (1):
    the score where all three hold the horizon and `normalized_score` is undefined (over
    different times held otherwise, so read it with the times to failure)."""
    rmse = {row: rows[row]["joint_rmse_rad"] for row in ROWS}
    if any(v is None for v in rmse.values()) or not rmse["floor"] > rmse["oracle"]:
        return None
    return float((rmse["floor"] - rmse["model"]) / (rmse["floor"] - rmse["oracle"]))

"""The trained model as the climbing robot's feedforward controller, in simulation.

Protocol (`symbench presets` shows its numbers, the preset's `closed_loop` group):

- References: up to `references` held-out test climbs of the run's split, from distinct
  symmetry orbits, chosen deterministically (`held_out_scenarios`), so every model of a
  split and seed tracks the same ones (on dataset v7's small preset all 32 `iid` test
  climbs, each a motion of its own). The horizon is the held-out climb's own length (the
  trajectories the model was trained on are as long), capped at the preset's `seconds`.
- Push (dataset v7; none on the v6 presets, whose records keep their meaning): each
  reference is climbed with a push on the base (`reference_push`: `push_n` newtons in the
  surface plane for `push_s`, its direction and its start within 30-60 % of the climb drawn
  from the scenario). The expert (the whole-body controller) climbs each reference again,
  pushed, recorded at every physics step (unpushed, its rows every 6 ms are the dataset's);
  every row below is pushed alike, at the same physics steps. The expert reacts to the push;
  the model must carry the robot through states off the nominal climb. Calibrated on hexa
  small (100 N for 0.1 s): the expert held all 32 `iid` references pushed with up to 150 N
  (26 at 250 N), the oracle replays them to rounding, the PD alone falls before the push,
  and a briefly trained SDNN (2 000 steps) held half as many of them as unpushed.
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
  reference). `tracking_score` (the headline score) places the model between floor (0) and
  oracle (1) on the tracking cost, per reference, then averages over references with a 95 %
  bootstrap interval (`tracking_score_ci95`; the board's intervals over seeds come on top).
  The tracking cost (`symbench.track`'s `tracking_cost`) is the mean over the horizon's
  steps of the RMS joint error relative to 0.2 rad, capped at 1, every step after a fall
  counting 1: it grows with the error and shrinks with the time held, continuously, so it
  neither saturates when every climb is held nor snaps to the gait event at which a climb
  is lost. `normalized_score` (the time held) and `normalized_rmse_score` (the joint RMSE
  over the time held) are kept as before.
- Which network (`judged`): the model trained on the `next` variant is not the run's own,
  so the metrics say which it is: its dataset's id and content hash, split, variant and
  seed, its checkpoint's hash (`model.safetensors`), steps, best step, why training
  stopped, its best validation loss, and its own open-loop torque RMSE on the references'
  rows every 6 ms (`open_loop_torque_rmse`; per reference in `per_reference`).
- One implementation: `symbench.ClosedLoopSetup` owns the references, gains, calibration
  (with its cache) and the model's rollouts; the site's clips run the same; this plugin
  turns its rows into metrics.
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
  step held), tracking cost. Per reference (`per_reference`): its scenario, push and
  open-loop error, the oracle's cost, and per fraction the model's and the floor's time
  held and cost and the model's score.
- Cost on 2 cores (hexa small v7, docs/concepts.md): the calibration about 30 s of CPU
  once per dataset, split and seed; the model's rollouts 30-50 s of CPU per run.

Headline (`success_rate`, `time_to_failure_s`, `tracking_score`, ... without prefix: the
model alone, PD fraction 0; `pd_*`: the headline fraction, the preset's `headline_pd`).
The headline fraction is 0.1: with it the PD alone (the floor) loses the path within a
fraction of the horizon while the oracle holds it, so the feedforward must carry the climb
(gravity, the magnets' reactions, the swing) and the score measures the model; at 1.0 the
servo gains alone track a climb (the floor holds), at 0 the unstable gait turns any torque
error into a fall within about a second, which measures little but the model's bias.
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from symbench.plugins.evaluators.closed_loop_score import mean_interval, reference_score

if TYPE_CHECKING:  # the simulation stack loads when a run evaluates, not with the command line
    from symbench import EvaluationContext, Push

NAME = "closed-loop"
DESCRIPTION = (
    "learned model as the feedforward controller tracking held-out climbs from distinct "
    "symmetry orbits, with joint PD at fractions of the servo gains; oracle, floor and "
    "expert rows calibrate it"
)
ROWS = ("model", "oracle", "floor")
CACHE_DIR = "closed-loop-cache"  # under the run's output folder


def trainings(context: EvaluationContext) -> list[tuple[str | None, str, str]]:
    """The model it tracks with: the `next` variant on the data for control, for a run to
    train ahead."""
    return [(context.control_dataset(), context.split, "next")]


def evaluate(context: EvaluationContext) -> dict:
    trained_on = context.control_dataset()  # the noisy variant of a standard dataset
    trained = context.on_dataset(trained_on, context.split, "next")
    from symbench import ClosedLoopSetup

    setup = ClosedLoopSetup(context.dataset, context.test_trajectories, context.preset.closed_loop)
    fractions = setup.fractions
    # None: the expert itself fell, no reference to track
    measured = setup.calibration(Path(context.output_dir) / CACHE_DIR)
    kept = [(f, m) for f, m in zip(setup.scenarios, measured, strict=True) if m is not None]
    calibration = [m for _, m in kept]
    # every reference at every fraction in lockstep: one model call per physics step
    references = [(m.scenario, m.reference) for m in calibration]
    tracked = iter(setup.track_model(trained.predict, context.entry.view, references))
    runs: dict[str, dict[float, list]] = {row: {f: [] for f in fractions} for row in ROWS}
    for m in calibration:
        for f in fractions:  # the order of the batch (`ClosedLoopSetup.job`)
            runs["model"][f].append(next(tracked))
            runs["oracle"][f].append(m.oracle)
            runs["floor"][f].append(m.floor[f])
    open_loop = setup.open_loop_rmse(trained.predict, context.entry.view, references)
    tried = len(setup.scenarios)
    horizons = [float(fields["seconds"]) for fields, _ in kept]
    orbits = [_describe(fields) for fields, _ in kept]
    headline = setup.headline
    budget = context.preset.closed_loop
    out: dict = {
        "trained_on": trained_on,
        "judged": {**trained.provenance, "open_loop_torque_rmse": _rms(open_loop)},
        "references": len(horizons),
        "orbits": orbits,
        "horizon_s": _mean(horizons),
        "push_n": budget.push_n,
        "push_s": budget.push_s,
        "pd_fractions": list(fractions),
        "headline_pd_fraction": headline,
        "pd_gains": list(setup.gains(headline)),
        "expert_success_rate": len(horizons) / tried if tried else None,
    }
    by_fraction: dict[str, dict] = {}
    scores: dict[float, list[float | None]] = {}
    for f in fractions:
        rows = {row: _summary(runs[row][f]) for row in ROWS}
        costs = zip(*(runs[row][f] for row in ROWS), strict=True)
        scores[f] = [
            reference_score(model.tracking_cost, floor.tracking_cost, oracle.tracking_cost)
            for model, oracle, floor in costs
        ]
        score, interval = mean_interval(scores[f])
        by_fraction[str(f)] = {
            **rows,
            "normalized_score": _normalized(rows, horizons),
            "normalized_rmse_score": _normalized_rmse(rows),
            "tracking_score": score,
            "tracking_score_ci95": interval,
        }
    out["by_pd_fraction"] = by_fraction
    out["per_reference"] = [
        {
            "scenario": orbits[i],
            "push": _as_dict(setup.push(m.scenario)),
            "open_loop_torque_rmse": open_loop[i],
            "oracle_tracking_cost": m.oracle.tracking_cost,
            "by_pd_fraction": {
                str(f): _reference_row(runs["model"][f][i], m.floor[f], scores[f][i])
                for f in fractions
            },
        }
        for i, m in enumerate(calibration)
    ]
    for prefix, f in (("", fractions[0]), ("pd_", headline)):
        part = by_fraction[str(f)]
        out.update({prefix + k: v for k, v in part["model"].items()})
        for key in ("normalized_score", "normalized_rmse_score", "tracking_score"):
            out[prefix + key] = part[key]
        out[prefix + "tracking_score_ci95"] = part["tracking_score_ci95"]
        for row in ("oracle", "floor"):
            out.update({f"{prefix}{row}_{k}": v for k, v in part[row].items() if k != "failures"})
    return out


def _describe(fields: dict) -> str:
    keys = ("inclination_deg", "heading_deg", "yaw_deg", "direction")
    return ", ".join(f"{k}={fields[k]}" for k in keys if k in fields)


def _mean(values: list[float]) -> float | None:
    """The mean, or None (JSON null: records hold no NaN) when there is nothing to average."""
    values = [v for v in values if not math.isnan(v)]
    return float(np.mean(values)) if values else None


def _reference_row(model: Any, floor: Any, score: float | None) -> dict:
    """One reference at one fraction: the model's and the floor's rollouts (`Tracking`s)."""
    return {
        "held_s": model.time_to_failure_s,
        "tracking_cost": model.tracking_cost,
        "floor_held_s": floor.time_to_failure_s,
        "floor_tracking_cost": floor.tracking_cost,
        "tracking_score": score,
    }


def _as_dict(push: Push | None) -> dict | None:
    return None if push is None else push.to_dict()


def _rms(values: list[float]) -> float | None:
    """The root mean square of per-reference RMSEs (references of one length: the RMSE over
    all their rows), or None."""
    return float(np.sqrt(np.mean(np.square(values)))) if values else None


def _summary(results: list) -> dict:
    return {
        "success_rate": _mean([float(r.attached) for r in results]),
        "time_to_failure_s": _mean([r.time_to_failure_s for r in results]),
        "joint_rmse_rad": _mean([r.joint_rmse_rad for r in results]),
        "base_drift_m": _mean([r.base_drift_m for r in results]),
        "base_drift_deg": _mean([r.base_drift_deg for r in results]),
        "tracking_cost": _mean([r.tracking_cost for r in results]),
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

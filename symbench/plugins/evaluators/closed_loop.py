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

import math
from pathlib import Path

import numpy as np

from symbench import ClosedLoopSetup, EvaluationContext
from symbench import held_out_scenarios as held_out_scenarios  # kept importable from here

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
    tried = len(setup.scenarios)
    horizons = [float(fields["seconds"]) for fields, _ in kept]
    orbits = [_describe(fields) for fields, _ in kept]
    headline = setup.headline
    out: dict = {
        "trained_on": trained_on,
        "references": len(horizons),
        "orbits": orbits,
        "horizon_s": _mean(horizons),
        "pd_fractions": list(fractions),
        "headline_pd_fraction": headline,
        "pd_gains": list(setup.gains(headline)),
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

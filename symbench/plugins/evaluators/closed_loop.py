"""The trained model as the climbing robot's feedforward controller, in simulation.

Protocol (`symbench presets` shows its numbers, the preset's `closed_loop` group):

- References: up to `references` held-out test climbs of the run's split, from distinct
  symmetry orbits, chosen deterministically (`held_out_scenarios`), so every model of a
  split and seed tracks the same ones. The expert (the whole-body controller) climbs each
  again, recorded at every physics step; its rows every 6 ms are the dataset's. The
  horizon is the held-out climb's own length (the trajectories the model was trained on
  are as long), capped at the preset's `seconds`.
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

import numpy as np

from symbench import EvaluationContext

NAME = "closed-loop"
DESCRIPTION = (
    "learned model as the feedforward controller tracking held-out climbs from distinct "
    "symmetry orbits, with joint PD at fractions of the servo gains; oracle, floor and "
    "expert rows calibrate it"
)
ROWS = ("model", "oracle", "floor")


def evaluate(context: EvaluationContext) -> dict:
    from symbench import Scenario, build_view, simulate, track

    trained = context.on_split(context.split, "next")
    frames, entry = context.dataset.frames, context.entry
    pair = np.zeros(2, dtype=np.int64)

    def model(rows: dict[str, np.ndarray]) -> np.ndarray:
        inputs = build_view(rows, pair, frames, entry.view, "next").inputs
        return trained.predict(inputs)[0]

    budget = context.preset.closed_loop
    control = context.robot.control
    fractions = tuple(float(f) for f in budget.pd_fractions)
    runs: dict[str, dict[float, list]] = {row: {f: [] for f in fractions} for row in ROWS}
    chosen = held_out_scenarios(
        context.dataset,
        context.test_trajectories,
        budget.references,
        context.robot.group.rotation_order,
    )
    tried, horizons, orbits = 0, [], []
    for fields in chosen:
        seconds = min(float(fields.get("seconds", budget.seconds)), budget.seconds)
        scenario = Scenario.from_dict({**fields, "seconds": seconds})
        tried += 1
        # the expert's climb recorded at every physics step: what `track` needs
        reference = simulate(scenario, record_period=control.timestep)
        if not reference.attached:  # the expert itself fell: no reference to track
            continue
        ref = reference.arrays
        horizons.append(seconds)
        orbits.append(_describe(fields))
        dt = float(ref["t"][1] - ref["t"][0])

        def oracle(rows: dict[str, np.ndarray], ref=ref, dt=dt) -> np.ndarray:
            return ref["tau"][int(round(float(rows["t"][0]) / dt))]

        def floor(rows: dict[str, np.ndarray], ref=ref) -> np.ndarray:
            return np.zeros_like(ref["tau"][0])

        policies = {"model": model, "oracle": oracle, "floor": floor}
        for f in fractions:
            gains = (f * control.kp, f * control.kd)
            for row in ROWS:
                runs[row][f].append(track(scenario, ref, policies[row], gains))
    headline = float(budget.headline_pd)
    out: dict = {
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


def held_out_scenarios(dataset, test_ids: np.ndarray, n: int, rotation_order: int = 1) -> list:
    """Scenarios of up to n test trajectories from distinct symmetry orbits, deterministic.

    Two scenarios whose yaws differ by a rotation of the robot's group (360 / order
    degrees) are images of each other (turned base, relabelled legs), so they share an
    orbit; so are climbs that differ only in heading, the whole scene turned about gravity,
    but the robot's group does not make them images, so they count as distinct after all
    the others. Test trajectories are taken in id order (ids skip the trajectories that
    failed in generation, so they are not positions): first one per orbit of the robot's
    motion (inclination, direction, leg order, yaw within the sector), then one per further
    heading of those.
    """
    by_id = dict(zip(np.asarray(dataset.trajectory_ids).tolist(), dataset.scenarios))
    sector = 360.0 / max(int(rotation_order), 1)
    candidates = [by_id[int(i)] for i in sorted(np.asarray(test_ids).tolist()) if int(i) in by_id]

    def motion(s: dict) -> tuple:
        yaw = round(float(s.get("yaw_deg", 0.0)) % sector, 6) % sector
        order = s.get("leg_order")
        return (
            float(s.get("inclination_deg", 0.0)),
            s.get("direction", "forward"),
            tuple(order) if order is not None else None,
            yaw,
        )

    chosen: list[dict] = []
    motions: set[tuple] = set()
    orbits: set[tuple] = set()
    for s in candidates:  # one per motion
        if len(chosen) < n and motion(s) not in motions:
            motions.add(motion(s))
            orbits.add((*motion(s), float(s.get("heading_deg", 0.0)) % 360.0))
            chosen.append(s)
    for s in candidates:  # then other headings of those motions
        orbit = (*motion(s), float(s.get("heading_deg", 0.0)) % 360.0)
        if len(chosen) < n and orbit not in orbits:
            orbits.add(orbit)
            chosen.append(s)
    return chosen


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

"""The climbs the closed loop tracks, the push each is climbed with, and the expert's own
torques replayed on them.

The pieces of the closed loop (`symbench.core.runs.closed_loop.ClosedLoopSetup`, which the
closed-loop evaluator and the leaderboard site's clips both run), public for evaluators of
their own.
"""

from __future__ import annotations

import zlib
from collections.abc import Sequence
from typing import TYPE_CHECKING

import numpy as np

from symbench.core.sim.scene.push import Push

# the share of a climb within which its push starts: after the start's transient, with time
# left to recover (or to fall) before the horizon
PUSH_WINDOW = (0.3, 0.6)
PUSH_DRAW = zlib.crc32(b"closed-loop push")  # tells the push's draws apart from others

if TYPE_CHECKING:
    from symbench.core.sim.scene.scenario import Scenario
    from symbench.core.sim.tracking.learned_control import Policy, TrackJob


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


def reference_scenarios(
    dataset, test_ids: np.ndarray, n: int, seconds: float, rotation_order: int = 1
) -> list[dict]:
    """The scenario fields of the closed loop's references (`held_out_scenarios`): each
    tracked over its climb's length capped at `seconds` (the preset's horizon), as the
    expert climbs it without noise (when the dataset is a noisy one)."""
    return [
        {
            **{k: v for k, v in fields.items() if k != "torque_noise"},
            "seconds": min(float(fields.get("seconds", seconds)), seconds),
        }
        for fields in held_out_scenarios(dataset, test_ids, n, rotation_order)
    ]


def reference_push(scenario: Scenario, force_n: float, duration_s: float) -> Push | None:
    """The push `scenario` is climbed with in the closed loop (None when `force_n` is 0):
    `force_n` newtons in the surface plane for `duration_s`, its direction (from downhill)
    and its start (within PUSH_WINDOW of the climb) drawn from the scenario's seed, so every
    row and every model of a reference meets the same push."""
    if not force_n:
        return None
    rng = np.random.default_rng([PUSH_DRAW, int(scenario.seed)])
    low, high = PUSH_WINDOW
    start = round(float(rng.uniform(low, high)) * float(scenario.seconds), 3)
    angle = float(rng.uniform(0.0, 2.0 * np.pi))
    force = (round(force_n * np.cos(angle), 6), round(force_n * np.sin(angle), 6), 0.0)
    return Push(start, duration_s, force)


def oracle_policy(reference: dict[str, np.ndarray]) -> Policy:
    """The expert's recorded torque of the current physics step (`reference` as
    `expert_reference` records it): tracked, it gives back the expert's climb to rounding
    at every PD gain (the closed loop's `oracle` row)."""
    tau = reference["tau"]
    dt = float(reference["t"][1] - reference["t"][0])
    return lambda rows: tau[int(round(float(rows["t"][0]) / dt))]


def model_jobs(
    references: Sequence[tuple[Scenario, dict[str, np.ndarray]]],
    fractions: Sequence[float],
    servo_gains: tuple[float, float],
    pushes: Sequence[Push | None] | None = None,
) -> list[TrackJob]:
    """The closed loop's rollouts of one model, in the evaluator's order: every reference
    (scenario, the expert's climb at every physics step, pushed by `pushes[i]` when given)
    at every PD fraction of the servo gains (Kp, Kd), fractions inner. `track_batch` of them
    with the model's policy is the evaluator's measurement; a model's torques may round
    differently in another batch, so whoever reproduces one of these rollouts runs this
    very batch."""
    from symbench.core.sim.tracking.learned_control import TrackJob

    kp, kd = servo_gains
    pushed = list(pushes) if pushes is not None else [None] * len(references)
    return [
        TrackJob(s, r, (f * kp, f * kd), push=p)
        for (s, r), p in zip(references, pushed, strict=True)
        for f in fractions
    ]

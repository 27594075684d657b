"""The closed loop of one split: a trained model as the climbing robot's feedforward
controller, tracking the expert's held-out climbs with a joint PD about them.

`ClosedLoopSetup` is the one implementation of it, for everyone who must track what the
closed-loop evaluator tracked: the evaluator itself (symbench/plugins/evaluators/
closed_loop.py, through the public API as `symbench.ClosedLoopSetup`) and the leaderboard
site's clips (symbench/core/board/site/clips.py). It owns

- the references: the scenario fields of up to `references` held-out test climbs from
  distinct symmetry orbits (`reference_scenarios`), the push each is climbed with (`push`,
  drawn from the scenario: the preset's `push_n` newtons in the surface plane for `push_s`,
  none on the v6 presets), and the expert's climb of each, pushed, recorded at every
  physics step (None where the expert itself fell); every row tracking a reference is pushed
  alike;
- the PD gains: fractions of the robot's servo gains (Kp, Kd), the preset's `pd_fractions`
  and its headline one;
- the calibration, which does not depend on the model: the `oracle` (the expert's recorded
  torques replayed, at the headline fraction: on the reference the PD vanishes, so it is
  the same at every fraction) and the `floor` (zero feedforward: the PD alone) at every
  fraction, kept in a cache folder when one is given, so a sweep measures it once;
- the model's open-loop error on the references (`open_loop_rmse`: its torques against the
  expert's on the references' rows every 6 ms, as in its test set);
- the model's rollouts: its policy (`feedforward_policy`) and the jobs of one batch
  (`model_jobs`: every reference at every fraction, fractions inner), run in lockstep by
  `track_batch`. A model's torques may round differently in another batch, so whoever
  reproduces one of these rollouts runs this very batch (`track_model`).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, replace
from functools import cached_property
from pathlib import Path
from typing import Any

import numpy as np

from symbench.core.common.fit_errors import rmse
from symbench.core.common.version import __version__
from symbench.core.config.presets import ClosedLoop
from symbench.core.data.views.transforms import build_view
from symbench.core.runs.closed_loop_cache import (
    CACHE_VERSION,
    Calibrated,
    cache_name,
    read_calibration,
    write_calibration,
)
from symbench.core.runs.control_policy import feedforward_policy
from symbench.core.sim.scene.push import Push
from symbench.core.sim.scene.scenario import Scenario
from symbench.core.sim.tracking.learned_control import (
    LOOKAHEAD_S,
    BatchPolicy,
    Observer,
    Tracking,
    track,
    track_batch,
)
from symbench.core.sim.tracking.references import (
    model_jobs,
    oracle_policy,
    reference_push,
    reference_scenarios,
)

Reference = tuple[Scenario, dict[str, np.ndarray]]  # a scenario, the expert's climb of it


@dataclass(frozen=True, eq=False)
class ClosedLoopSetup:
    """The closed loop on `dataset`'s test climbs `test_ids` (trajectory ids), with the
    preset's `budget` (`Preset.closed_loop`: horizon, references, PD fractions)."""

    dataset: Any  # symbench.core.data.dataset.Dataset
    test_ids: np.ndarray
    budget: ClosedLoop

    @property
    def fractions(self) -> tuple[float, ...]:
        """The PD fractions of the servo gains, in the preset's order."""
        return tuple(float(f) for f in self.budget.pd_fractions)

    @property
    def headline(self) -> float:
        """The headline PD fraction (the `pd_*` metrics)."""
        return float(self.budget.headline_pd)

    @property
    def servo_gains(self) -> tuple[float, float]:
        control = self.dataset.spec.control
        return control.kp, control.kd

    def gains(self, fraction: float) -> tuple[float, float]:
        """The PD gains (kp, kd) at `fraction` of the servo gains."""
        kp, kd = self.servo_gains
        return fraction * kp, fraction * kd

    @cached_property
    def scenarios(self) -> list[dict[str, Any]]:
        """The references' scenario fields, as tracked (noise-free, capped at the horizon)."""
        return reference_scenarios(
            self.dataset,
            self.test_ids,
            self.budget.references,
            self.budget.seconds,
            self.dataset.spec.group.rotation_order,
        )

    def push(self, scenario: Scenario) -> Push | None:
        """The push `scenario` is climbed and tracked with (None: the preset pushes not)."""
        return reference_push(scenario, self.budget.push_n, self.budget.push_s)

    def expert(self, fields: dict[str, Any]) -> Reference | None:
        """The expert's climb of `fields`, pushed, recorded at every physics step (what
        `track` needs), or None when the expert fell: no reference to track."""
        from symbench.core.sim.climb.rollout import simulate

        scenario = Scenario.from_dict(fields)
        timestep = self.dataset.spec.control.timestep
        reference = simulate(scenario, record_period=timestep, push=self.push(scenario))
        return (scenario, reference.arrays) if reference.attached else None

    @cached_property
    def references(self) -> list[Reference]:
        """The references the expert held, in order: those the model tracks."""
        return [r for r in map(self.expert, self.scenarios) if r is not None]

    def oracle(
        self, scenario: Scenario, reference: dict[str, np.ndarray], observe: Observer | None = None
    ) -> Tracking:
        """The expert's recorded torques replayed at the headline fraction: its climb again,
        to rounding; `observe` sees the physics after every step."""
        policy = oracle_policy(reference)
        gains, push = self.gains(self.headline), self.push(scenario)
        return track(scenario, reference, policy, gains, observe=observe, push=push)

    def floor(self, scenario: Scenario, reference: dict[str, np.ndarray]) -> dict[float, Tracking]:
        """The PD alone (zero feedforward) at every fraction."""

        def zero(rows: dict[str, np.ndarray]) -> np.ndarray:
            return np.zeros_like(reference["tau"][0])

        push = self.push(scenario)
        return {
            f: track(scenario, reference, zero, self.gains(f), push=push) for f in self.fractions
        }

    def calibration(self, cache: Path | None = None) -> list[Calibrated | None]:
        """Per reference scenario: None where the expert fell, else its reference with the
        oracle and the floor. None of it depends on the model: with a `cache` folder it is
        kept there (keyed by dataset content, robot, references and fractions) and read back
        by the next model of a sweep."""
        folder = None if cache is None else Path(cache) / cache_name(self._cache_key())
        if folder is not None:
            cached = read_calibration(folder, self._cache_key(), self.fractions)
            if cached is not None:
                return cached
        out: list[Calibrated | None] = []
        for fields in self.scenarios:
            expert = self.expert(fields)
            if expert is None:
                out.append(None)
                continue
            scenario, reference = expert
            out.append(
                Calibrated(
                    scenario,
                    reference,
                    self.oracle(scenario, reference),
                    self.floor(scenario, reference),
                )
            )
        if folder is not None:
            write_calibration(folder, self._cache_key(), out)
        return out

    def policy(
        self, predict: Callable[[dict[str, np.ndarray]], np.ndarray], view: str
    ) -> BatchPolicy:
        """A trained model (`predict` on `view` inputs, trained on the `next` variant) as the
        batch policy of `track_batch`."""
        return feedforward_policy(predict, self.dataset.frames, view)

    def open_loop_rmse(
        self,
        predict: Callable[[dict[str, np.ndarray]], np.ndarray],
        view: str,
        references: list[Reference],
    ) -> list[float]:
        """Per reference, the model's torque RMSE (N m) against the expert's on the
        reference's rows every LOOKAHEAD_S (the record period its `next` variant was
        trained on: for an unpushed climb the dataset's very rows): its open-loop test error
        on the climbs it tracks, beside how it tracks them."""
        out = []
        for _, reference in references:
            dt = float(reference["t"][1] - reference["t"][0])
            every = max(1, int(round(LOOKAHEAD_S / dt)))
            rows = {c: column[::every] for c, column in reference.items()}
            ids = np.zeros(len(rows["t"]), dtype=np.int64)
            arrays = build_view(rows, ids, self.dataset.frames, view, "next")
            out.append(float(rmse(predict(arrays.inputs), arrays.target)))
        return out

    def job(self, reference: int, fraction: float) -> int:
        """The index, in `track_model`'s batch, of reference `reference` at `fraction`."""
        return reference * len(self.fractions) + self.fractions.index(fraction)

    def track_model(
        self,
        predict: Callable[[dict[str, np.ndarray]], np.ndarray],
        view: str,
        references: list[Reference],
        observers: Mapping[int, Observer] | None = None,
    ) -> list[Tracking]:
        """The model's rollouts, the evaluator's measurement: every reference at every
        fraction (fractions inner, see `job`) in one lockstep batch; `observers` by job
        index see the physics of theirs."""
        pushes = [self.push(scenario) for scenario, _ in references]
        jobs = model_jobs(references, self.fractions, self.servo_gains, pushes)
        for i, observe in (observers or {}).items():
            jobs[i] = replace(jobs[i], observe=observe)
        return track_batch(jobs, self.policy(predict, view))

    # --- the calibration's cache ----------------------------------------------------------

    def _cache_key(self) -> dict[str, Any]:
        return {
            "cache_version": CACHE_VERSION,
            "symbench": __version__,
            "dataset_content_hash": self.dataset.content_hash,
            "robot_spec_hash": self.dataset.spec.spec_hash(),
            "scenarios": self.scenarios,
            "pd_fractions": list(self.fractions),
            "oracle_pd_fraction": self.headline,
            "servo_gains": list(self.servo_gains),
            "push": [self.budget.push_n, self.budget.push_s],
        }

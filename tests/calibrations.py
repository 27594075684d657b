"""A closed-loop calibration made without a simulator (the expert fell on one reference and
held the other, on random rows), the cache key it is kept under, and the check that a
calibration read back is exactly it."""

from __future__ import annotations

import numpy as np
from synthetic_raw import synthetic_raw

from symbench.core.runs.closed_loop_cache import Calibrated
from symbench.core.sim.scene.scenario import Scenario
from symbench.core.sim.tracking.learned_control import Tracking

FRACTIONS = (0.0, 0.1)
SCENARIOS = [
    {"robot": "hexa", "inclination_deg": 90.0, "seconds": 0.5, "yaw_deg": 0.0},
    {"robot": "hexa", "inclination_deg": 90.0, "seconds": 0.5, "yaw_deg": 60.0},
]
KEY = {"cache_version": 3, "scenarios": SCENARIOS, "pd_fractions": list(FRACTIONS)}


def tracking(held: bool) -> Tracking:
    return Tracking(held, None if held else "base dropped", 0.5, 0.01, 80, 0.02, 0.0, 0.1, 0.2)


def calibration() -> list[Calibrated | None]:
    """The expert fell on the first scenario and held the second."""
    scenario = Scenario.from_dict(SCENARIOS[1])
    floor = {f: tracking(False) for f in FRACTIONS}
    return [None, Calibrated(scenario, synthetic_raw(6, 8, seed=1), tracking(True), floor)]


def assert_as_written(read: list[Calibrated | None] | None) -> None:
    assert read is not None and read[0] is None
    written = calibration()[1]
    assert (read[1].scenario, read[1].oracle, read[1].floor) == (
        written.scenario,
        written.oracle,
        written.floor,
    )
    assert read[1].reference.keys() == written.reference.keys()
    for name, column in written.reference.items():
        np.testing.assert_array_equal(read[1].reference[name], column)

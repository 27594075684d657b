"""Whatever period a log was taken at, and whatever import.json declares, an import that
resamples gives a one-line error naming the input and leaves the cache as it was, or a
dataset at the robot's record period holding the rows the plan says: never an internal
error."""

from __future__ import annotations

import json

import numpy as np
from hypothesis import event, given
from hypothesis import strategies as st
from sandbox import fresh_home
from synthetic_raw import RECORD_PERIOD, synthetic_raw
from test_import_properties import LEGS, assert_refused

from symbench.core.common.errors import SymbenchError
from symbench.core.data.importing.derive import resample_plan
from symbench.core.data.importing.importer import import_logs
from symbench.core.data.importing.logs import PERIOD_TOLERANCE
from symbench.core.data.storage.files import read_trajectory

# periods a robot logs at, from well below the record period to a little above it
PERIODS = st.sampled_from([0.001, 0.002, 0.0025, 0.003, 0.004, 0.0045, 0.006]) | st.floats(
    1e-4, 0.0065
)


@given(
    period=PERIODS,
    declared=st.integers(0, 3).flatmap(lambda i: st.none() if i else PERIODS),  # None: right
    steps=st.integers(2, 80) | st.just(1),
    jitter=st.sampled_from([0.0, 0.01, 0.04]) | st.floats(0, 0.2),  # of the period
    seed=st.integers(0, 3),
)
def test_a_resampled_import_is_refused_naming_it_or_at_the_record_period(
    tmp_path_factory, period, declared, steps, jitter, seed
):
    folder = tmp_path_factory.mktemp("log")
    raw = synthetic_raw(LEGS, steps, seed=seed)
    noise = np.random.default_rng(seed).uniform(-jitter, jitter, steps) * period
    raw["t"] = np.arange(steps) * period + noise  # a log's clock: not quite regular
    np.savez(folder / "run.npz", **raw)
    stated = period if declared is None else declared
    (folder / "import.json").write_text(json.dumps({"robot": "hexa", "record_period_s": stated}))
    with fresh_home() as home:
        try:
            dataset = import_logs(folder, "resampled")
        except SymbenchError as error:
            event("refused")
            assert_refused(error, home, str(folder))
            return
        event(resample_plan(stated, RECORD_PERIOD)[0])
        stored = read_trajectory(dataset.root / dataset.metadata["trajectories"][0]["file"], LEGS)
    t = stored["t"]
    assert len(t) >= 2 and t[0] == raw["t"][0] and t[-1] <= raw["t"][-1] + 1e-9
    # the robot's record period, within the tolerances on the declared period and on each step
    assert np.allclose(np.diff(t), RECORD_PERIOD, rtol=(1 + PERIOD_TOLERANCE) ** 2 - 1)

"""Whatever import.json and the log files hold, `symbench data import` gives a one-line error
naming the input and leaves the cache as it was, or a dataset of exactly those logs."""

from __future__ import annotations

import json

import numpy as np
import pyarrow as pa
import pyarrow.parquet as pq
import pytest
from hypothesis import event, given
from hypothesis import strategies as st
from sandbox import files_under, fresh_home
from strategies import FILE_BYTES, NASTY_TEXT, changed, changed_npz, defective, edited
from synthetic_raw import N_LEGS, synthetic_raw, write_logs

from symbench.core.common.errors import SymbenchError
from symbench.core.data.importing.derive import DERIVABLE, derivative
from symbench.core.data.importing.importer import import_logs
from symbench.core.data.storage.columns import flatten, unflatten
from symbench.core.data.storage.files import read_trajectory, trajectory_bytes
from symbench.core.robot.specs import load_robot
from symbench.core.sim.raw import COLUMN_NAMES

LEGS = N_LEGS["hexa"]
PHYSICS_STEP = load_robot("hexa").control.timestep  # what the importer derives over
SCENARIOS = [
    {"heading_deg": 0.0, "yaw_deg": 60.0 * i, "leg_order": [0, 1, 2, 3, 4, 5]} for i in range(3)
]
MANIFEST = {
    "robot": "hexa",
    "record_period_s": 0.006,
    "trajectories": [{"file": f"run{i}.npz", "scenario": s} for i, s in enumerate(SCENARIOS)],
}


@pytest.fixture(scope="module")
def logs(tmp_path_factory):
    return write_logs(tmp_path_factory.mktemp("logs"), n_files=3)


def assert_refused(error: SymbenchError, home, *names: str) -> None:
    """One line, naming one of `names`, and nothing left in the cache."""
    message = str(error)
    assert message and "\n" not in message
    assert any(name in message for name in names), message
    assert files_under(home) in ([], ["datasets"])


def assert_same_columns(stored: dict[str, np.ndarray], written: dict[str, np.ndarray]) -> None:
    """The log's own columns exactly; an acceleration it lacks derived from its velocities."""
    for name in COLUMN_NAMES:
        if name in written:
            np.testing.assert_array_equal(stored[name], np.asarray(written[name], np.float64), name)
            continue
        assert name in DERIVABLE, f"{name} was neither given nor derivable"
        t, source = np.asarray(written["t"], np.float64), stored[DERIVABLE[name]]
        np.testing.assert_array_equal(stored[name], derivative(t, source, PHYSICS_STEP), name)


@given(manifest=NASTY_TEXT | edited(MANIFEST).map(json.dumps))
def test_any_import_json_gives_an_error_or_exactly_what_it_lists(logs, manifest):
    (logs / "import.json").write_text(manifest)
    with fresh_home() as home:
        try:
            dataset = import_logs(logs, "logs")
        except SymbenchError as error:
            assert_refused(error, home, str(logs), "robot")
            return
        listed = json.loads(manifest).get("trajectories") or [
            {"file": p.name} for p in sorted(logs.glob("*.npz"))
        ]
        stored = dataset.metadata["trajectories"]
        assert [r["source_file"] for r in stored] == [e["file"] for e in listed]
        for record, entry in zip(stored, listed):
            given = entry.get("scenario", {})
            assert {k: record["scenario"][k] for k in given} == given
            with np.load(logs / entry["file"]) as npz:
                assert_same_columns(read_trajectory(dataset.root / record["file"], LEGS), npz)


@given(fmt=st.sampled_from(["npz", "parquet"]), data=st.data())
def test_any_log_file_gives_an_error_naming_it_or_its_exact_values(tmp_path_factory, fmt, data):
    raw = synthetic_raw(LEGS, 12, seed=3)
    folder = tmp_path_factory.mktemp("log")
    path = folder / f"run.{fmt}"
    if fmt == "npz":
        written = data.draw(defective(raw, same_length=False))
        np.savez(path, **written)
    else:
        written = data.draw(defective(flatten(raw, LEGS), same_length=True))
        pq.write_table(pa.table(written), path)
    (folder / "import.json").write_text(
        json.dumps({**MANIFEST, "trajectories": [{"file": path.name}]})
    )
    with fresh_home() as home:
        try:
            dataset = import_logs(folder, "log")
        except SymbenchError as error:
            assert_refused(error, home, str(path))
            return
        assert all(np.asarray(v).dtype != object for v in written.values())  # no pickle is loaded
        stored = read_trajectory(dataset.root / dataset.metadata["trajectories"][0]["file"], LEGS)
        assert_same_columns(
            stored, written if fmt == "npz" else unflatten(written, LEGS, "written")
        )


@given(fmt=st.sampled_from(["npz", "parquet"]), content=FILE_BYTES)
def test_a_log_file_of_arbitrary_bytes_is_named(tmp_path_factory, fmt, content):
    folder = tmp_path_factory.mktemp("log")
    path = folder / f"run.{fmt}"
    path.write_bytes(content)
    (folder / "import.json").write_text(
        json.dumps({**MANIFEST, "trajectories": [{"file": path.name}]})
    )
    with fresh_home() as home, pytest.raises(SymbenchError) as error:
        import_logs(folder, "log")
    assert_refused(error.value, home, str(path))


@given(fmt=st.sampled_from(["npz", "parquet"]), data=st.data())
def test_a_log_file_with_bytes_changed_is_named_or_read_as_numpy_reads_it(
    tmp_path_factory, fmt, data
):
    """Damage within a valid file: its header's shape or dtype changed, its bytes changed, cut
    or repeated (an npz with its checksums right, so numpy's parser sees the damage)."""
    raw = synthetic_raw(LEGS, 12, seed=3)
    folder = tmp_path_factory.mktemp("log")
    path = folder / f"run.{fmt}"
    if fmt == "npz":
        path.write_bytes(data.draw(changed_npz(raw)))
    else:
        path.write_bytes(data.draw(changed(trajectory_bytes(raw, LEGS))))
    (folder / "import.json").write_text(
        json.dumps({**MANIFEST, "trajectories": [{"file": path.name}]})
    )
    with fresh_home() as home:
        try:
            dataset = import_logs(folder, "log")
        except SymbenchError as error:
            event("refused")
            assert_refused(error, home, str(path))
            return
        stored = read_trajectory(dataset.root / dataset.metadata["trajectories"][0]["file"], LEGS)
    event("imported")
    if fmt == "npz":  # read here as numpy reads it, now that symbench found it sound
        with np.load(path, allow_pickle=False) as npz:
            written = {k: npz[k] for k in npz.files}
    else:
        written = unflatten(pq.read_table(path).to_pydict(), LEGS, str(path))
    assert_same_columns(stored, written)

"""Whatever a closed-loop cache folder holds (calibration.json of any bytes or edited field by
field; a reference's npz damaged inside, re-hashed into calibration.json or not), reading it
gives a calibration of well-typed rows whose references are the bytes their digests name, or
None (measured again): never an exception."""

from __future__ import annotations

import hashlib
import json
import shutil
import tempfile
from pathlib import Path

import numpy as np
import pytest
from calibrations import FRACTIONS, KEY, calibration
from hypothesis import event, given
from hypothesis import strategies as st
from strategies import FILE_BYTES, changed, changed_npz, edited

from symbench.core.runs.closed_loop_cache import CALIBRATION, read_calibration, write_calibration
from symbench.core.sim.tracking.learned_control import Tracking

REFERENCE = "reference-1.npz"  # the second scenario's: the expert held it


@pytest.fixture(scope="module")
def cached(tmp_path_factory) -> Path:
    folder = tmp_path_factory.mktemp("cache")
    write_calibration(folder, KEY, calibration())
    return folder


def read_copy(cached: Path, calibration_json: bytes | None, reference: bytes | None):
    """The calibration read from a copy of `cached` with these files' bytes put in."""
    with tempfile.TemporaryDirectory() as scratch:
        folder = shutil.copytree(cached, Path(scratch) / "cache")
        if calibration_json is not None:
            (folder / CALIBRATION).write_bytes(calibration_json)
        if reference is not None:
            (folder / REFERENCE).write_bytes(reference)
        return read_calibration(folder, KEY, FRACTIONS)


def assert_sound(read, reference: bytes) -> None:
    """A calibration of typed rows, its one reference the arrays of `reference`."""
    assert isinstance(read, list) and len(read) == len(KEY["scenarios"])
    for item in read:
        if item is None:
            continue
        for row in (item.oracle, *item.floor.values()):
            assert isinstance(row, Tracking) and isinstance(row.attached, bool)
            assert isinstance(row.steps, int) and not isinstance(row.steps, bool)
        assert tuple(item.floor) == FRACTIONS
        with tempfile.TemporaryDirectory() as scratch:
            path = Path(scratch) / REFERENCE
            path.write_bytes(reference)
            with np.load(path, allow_pickle=False) as npz:
                assert item.reference.keys() == set(npz.files)
                for name in npz.files:
                    np.testing.assert_array_equal(item.reference[name], npz[name])


@given(data=st.data())
def test_any_calibration_json_reads_as_typed_rows_or_is_measured_again(cached, data):
    body = json.loads((cached / CALIBRATION).read_text())
    rows = edited(body["references"]).map(lambda r: {**body, "references": r})  # not the key
    content = data.draw(FILE_BYTES | (edited(body) | rows).map(lambda b: json.dumps(b).encode()))
    read = read_copy(cached, content, None)
    event("measured again" if read is None else "read")
    if read is not None:
        assert_sound(read, (cached / REFERENCE).read_bytes())


@given(data=st.data(), rehash=st.booleans())
def test_a_damaged_reference_is_measured_again_or_read_as_its_digest_names(cached, data, rehash):
    original = (cached / REFERENCE).read_bytes()
    with np.load(cached / REFERENCE) as npz:
        arrays = {k: npz[k] for k in npz.files}
    content = data.draw(changed_npz(arrays) | changed(original) | FILE_BYTES)
    body = None
    if rehash:  # its digest written into calibration.json by hand
        rows = json.loads((cached / CALIBRATION).read_text())
        rows["references"][1]["reference_sha256"] = hashlib.sha256(content).hexdigest()
        body = json.dumps(rows).encode()
    read = read_copy(cached, body, content)
    event("measured again" if read is None else "read")
    if read is not None:
        assert rehash or content == original
        assert_sound(read, content)

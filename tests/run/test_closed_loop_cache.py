"""The closed-loop calibration's cache: read back as written, and a damaged or crafted cache
folder measured again, never trusted and never an internal error."""

from __future__ import annotations

import hashlib
import json

import numpy as np
import pytest
from calibrations import FRACTIONS, KEY, assert_as_written, calibration
from crafted_npz import claim_rows

from symbench.core.runs.closed_loop_cache import CALIBRATION, read_calibration, write_calibration


@pytest.fixture
def cached(tmp_path):
    write_calibration(tmp_path, KEY, calibration())
    return tmp_path


def rehash(folder) -> None:
    """The reference's SHA-256 in calibration.json made that of its file as it is now."""
    body = json.loads((folder / CALIBRATION).read_text())
    digest = hashlib.sha256((folder / "reference-1.npz").read_bytes()).hexdigest()
    body["references"][1]["reference_sha256"] = digest
    (folder / CALIBRATION).write_text(json.dumps(body))


def test_a_calibration_reads_back_as_written(cached):
    assert_as_written(read_calibration(cached, KEY, FRACTIONS))


def test_another_key_or_other_fractions_read_as_missing(cached):
    assert read_calibration(cached, {**KEY, "cache_version": 2}, FRACTIONS) is None
    assert read_calibration(cached, KEY, (0.0, 0.3)) is None


def test_a_reference_re_hashed_with_a_header_claiming_terabytes_is_measured_again(cached):
    """Before: np.load allocated what the header claimed (MemoryError: an internal error
    in the closed-loop evaluator)."""
    claim_rows(cached / "reference-1.npz", "tau", 10**12)
    rehash(cached)
    assert read_calibration(cached, KEY, FRACTIONS) is None


def test_a_reference_edited_in_place_is_measured_again(cached):
    """Before: a reference whose numbers were changed was read and tracked as the expert's
    climb (the cache named no digest)."""
    path = cached / "reference-1.npz"
    with np.load(path) as npz:
        arrays = {k: npz[k] for k in npz.files}
    arrays["tau"] = arrays["tau"] + 1.0
    np.savez(path, **arrays)
    assert read_calibration(cached, KEY, FRACTIONS) is None


@pytest.mark.parametrize(
    "edit",
    [
        lambda body: body["references"][1]["oracle"].update(joint_rmse_rad="0.01"),
        lambda body: body["references"][1]["oracle"].pop("steps"),
        lambda body: body["references"][1]["floor"][0].append(1),
        lambda body: body["references"].append(None),
    ],
    ids=["text for a number", "a field missing", "a floor row too long", "a row too many"],
)
def test_a_row_of_other_fields_or_types_is_measured_again(cached, edit):
    body = json.loads((cached / CALIBRATION).read_text())
    edit(body)
    (cached / CALIBRATION).write_text(json.dumps(body))
    assert read_calibration(cached, KEY, FRACTIONS) is None


def test_json_nested_past_the_recursion_limit_is_measured_again(cached):
    (cached / CALIBRATION).write_text("[" * 100_000 + "]" * 100_000)
    assert read_calibration(cached, KEY, FRACTIONS) is None

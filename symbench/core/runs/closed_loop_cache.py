"""The closed-loop calibration's cache (`ClosedLoopSetup.calibration(cache)`): the expert's
references and their oracle and floor rows, which do not depend on the model, kept in a
folder named by their key so that a sweep measures them once.

A cache folder that is incomplete, of another key or damaged reads as missing and is
measured again: a reference whose bytes are not those written (each is named by its
SHA-256), an array header claiming more than its file holds (a reference re-hashed by hand:
`read_npz`), a row of other fields or types, or JSON nested past the recursion limit. A
damaged cache is never trusted, and never an internal error."""

from __future__ import annotations

import hashlib
import io
import json
from dataclasses import MISSING, dataclass, fields
from pathlib import Path
from typing import Any

import numpy as np

from symbench.core.common.atomic import write_bytes_atomic
from symbench.core.common.errors import SymbenchError
from symbench.core.common.hashing import sha256_file
from symbench.core.data.storage.npz import read_npz
from symbench.core.sim.scene.scenario import Scenario
from symbench.core.sim.tracking.learned_control import Tracking

CACHE_VERSION = 3  # bump when what is cached, or how it is measured, changes
CALIBRATION = "calibration.json"  # written last: its presence means the folder is complete
# what reading a damaged folder may raise; each means "measure it again"
DAMAGE = (OSError, ValueError, KeyError, TypeError, RecursionError, SymbenchError)
# a Tracking row's fields that are not plain numbers (int or float, not bool)
_TYPES: dict[str, tuple[type, ...]] = {
    "attached": (bool,),
    "failure": (str, type(None)),
    "steps": (int,),
}


@dataclass(frozen=True)
class Calibrated:
    """One reference the expert held, with the rows that do not depend on the model."""

    scenario: Scenario
    reference: dict[str, np.ndarray]  # the expert's climb at every physics step
    oracle: Tracking  # the expert's recorded torques replayed (at the headline fraction)
    floor: dict[float, Tracking]  # the PD alone, per fraction


def cache_name(key: dict[str, Any]) -> str:
    """The cache folder's name: a digest of everything the calibration depends on."""
    text = json.dumps(key, sort_keys=True, separators=(",", ":"))
    return hashlib.sha256(text.encode()).hexdigest()[:20]


def write_calibration(folder: Path, key: dict[str, Any], measured: list[Calibrated | None]) -> None:
    """References as .npz (exact float64), each named with its SHA-256, then
    calibration.json last."""
    rows: list[Any] = []
    for i, item in enumerate(measured):
        if item is None:
            rows.append(None)
            continue
        npz, arrays = io.BytesIO(), dict[str, Any](item.reference)
        np.savez(npz, **arrays)
        write_bytes_atomic(folder / f"reference-{i}.npz", npz.getvalue())
        rows.append(
            {
                "reference_sha256": hashlib.sha256(npz.getvalue()).hexdigest(),
                "oracle": dict(vars(item.oracle)),
                "floor": [[f, dict(vars(r))] for f, r in item.floor.items()],
            }
        )
    body = json.dumps({"key": key, "references": rows}, indent=1)
    write_bytes_atomic(folder / CALIBRATION, body.encode())


def read_calibration(
    folder: Path, key: dict[str, Any], fractions: tuple[float, ...]
) -> list[Calibrated | None] | None:
    """The calibration cached in `folder` when it is complete, of this very `key` (its
    scenarios in order), at these PD `fractions` and as written; else None."""
    try:
        data = json.loads((folder / CALIBRATION).read_text())
        if data["key"] != json.loads(json.dumps(key)):
            return None
        out: list[Calibrated | None] = []
        rows = zip(key["scenarios"], data["references"], strict=True)
        for i, (scenario, row) in enumerate(rows):
            if row is None:
                out.append(None)
                continue
            path = folder / f"reference-{i}.npz"
            if sha256_file(path) != row["reference_sha256"]:
                return None
            floor = {float(f): _tracking(r) for f, r in row["floor"]}
            if tuple(floor) != fractions:
                return None
            oracle, reference = _tracking(row["oracle"]), read_npz(path)
            out.append(Calibrated(Scenario.from_dict(scenario), reference, oracle, floor))
        return out
    except DAMAGE:
        return None


def _tracking(row: Any) -> Tracking:
    """A Tracking from its cached row: its fields (those with a default may be left out),
    each of its type."""
    names = {f.name for f in fields(Tracking)}
    required = {f.name for f in fields(Tracking) if f.default is MISSING}
    if not isinstance(row, dict) or set(row) - names or required - set(row):
        raise ValueError(f"a tracking row has fields {sorted(names)}")
    for name, value in row.items():
        types = _TYPES.get(name, (int, float))
        if not isinstance(value, types) or (isinstance(value, bool) and bool not in types):
            raise TypeError(f"tracking field {name} is {value!r}")
    return Tracking(**row)

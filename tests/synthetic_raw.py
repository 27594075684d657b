"""Synthetic raw trajectories that obey symbench/core/sim/raw.py, and a stand-in simulator.

They let storage, views, splits and generation be tested without MuJoCo: the numbers are
random but shaped and typed exactly as the recorder writes them.
"""

from __future__ import annotations

import json
import zlib
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from symbench.core.common.errors import SymbenchError
from symbench.core.sim.scene.scenario import Scenario

RECORD_PERIOD = 0.006


def synthetic_raw(n_legs: int, n_steps: int, seed: int = 0) -> dict[str, np.ndarray]:
    """Random raw columns for one trajectory of `n_steps` steps."""
    rng = np.random.default_rng(seed)
    quat = rng.normal(size=(n_steps, 4))
    quat /= np.linalg.norm(quat, axis=1, keepdims=True)
    return {
        "t": np.arange(n_steps) * RECORD_PERIOD,
        "base_pos": np.cumsum(rng.normal(scale=1e-3, size=(n_steps, 3)), axis=0),
        "base_quat": quat,
        "base_linvel": rng.normal(size=(n_steps, 3)),
        "base_angvel": rng.normal(size=(n_steps, 3)),
        "base_linacc": rng.normal(size=(n_steps, 3)),
        "q": rng.normal(size=(n_steps, n_legs, 3)),
        "qd": rng.normal(size=(n_steps, n_legs, 3)),
        "qdd": rng.normal(size=(n_steps, n_legs, 3)),
        "tau": rng.normal(size=(n_steps, n_legs, 3)),
        "contact": rng.integers(0, 2, size=(n_steps, n_legs)).astype(np.uint8),
        "magnet": rng.integers(0, 2, size=(n_steps, n_legs)).astype(np.uint8),
    }


@dataclass
class FakeRollout:
    arrays: dict[str, np.ndarray]
    attached: bool
    failure: str | None


N_LEGS = {"magneto": 4, "hexa": 6, "nona": 9}


def fake_simulate(scenario: Scenario, record_period: float = RECORD_PERIOD) -> FakeRollout:
    """Deterministic per scenario; seed 13 'detaches', seed 14 stops the 'controller'."""
    if scenario.seed == 14:
        raise SymbenchError("whole-body QP not solved (infeasible)")
    key = zlib.crc32(json.dumps(scenario.to_dict(), sort_keys=True).encode())
    n_steps = int(round(scenario.seconds / record_period))
    arrays = synthetic_raw(N_LEGS[scenario.robot], n_steps, seed=key)
    if scenario.seed == 13:
        return FakeRollout(arrays, False, "foot 2 left the surface at 0.3 s")
    return FakeRollout(arrays, True, None)


def write_logs(folder, robot: str = "hexa", n_files: int = 6, n_steps: int = 20) -> Path:
    """A folder that `symbench data import` takes: npz logs of `robot` and an import.json."""
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    for i in range(n_files):
        np.savez(folder / f"run{i}.npz", **synthetic_raw(N_LEGS[robot], n_steps, seed=i))
    (folder / "import.json").write_text(
        json.dumps({"robot": robot, "record_period_s": RECORD_PERIOD})
    )
    return folder

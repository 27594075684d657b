"""Make the small log set of the data-symmetry tests: magneto on a wall, each climb's leg
order logged as the order in which its legs stepped (what a robot's logger knows).

    python tests/data/symmetry/logs/make_log.py   # rewrites magneto-gaits/ beside it

Four climbs, simulated by symbench's own generator and logged at the record period (6 ms,
every raw column):

- `a`: yaw 0, legs stepping 0, 1, 3, 2 (0.8 s);
- `b`: its image under the half turn: yaw 180, legs stepping 2, 3, 1, 0 (the same order
  relabelled), logged from 252 ms (42 rows) into the climb and 252 ms longer than `a`: the
  same motion at another phase of its gait;
- `c`: yaw 0, legs stepping 2, 3, 1, 0 (0.8 s);
- `d`: its image, in phase: yaw 180, legs stepping 0, 1, 3, 2 (0.8 s).

`a` and `d` (like `c` and `b`) log the same list of legs at yaws 180 degrees apart, which
are not images of each other. The simulator's scenario takes the leg order of the yaw's first
sector and turns it with the base (`Climb.from_scenario`), so the climb stepping 2, 3, 1, 0
at yaw 180 is the scenario with leg order 0, 1, 3, 2.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pyarrow as pa
import pyarrow.parquet as pq

from symbench.core.data.storage.columns import flatten
from symbench.core.sim.climb.rollout import simulate
from symbench.core.sim.scene.scenario import Scenario
from symbench.core.sim.scene.setup import Climb

FOLDER = Path(__file__).parent / "magneto-gaits"
SECONDS = 0.8
LATE_ROWS = 42  # b starts 42 records (252 ms) into its climb
# name: (yaw, the scenario's leg order (the yaw's first sector), seconds simulated, first row)
CLIMBS = {
    "a": (0.0, (0, 1, 3, 2), SECONDS, 0),
    "b": (180.0, (0, 1, 3, 2), SECONDS + 2 * LATE_ROWS * 0.006, LATE_ROWS),
    "c": (0.0, (2, 3, 1, 0), SECONDS, 0),
    "d": (180.0, (2, 3, 1, 0), SECONDS, 0),
}


def main() -> None:
    FOLDER.mkdir(parents=True, exist_ok=True)
    entries = []
    for name, (yaw, order, seconds, first) in CLIMBS.items():
        scenario = Scenario(
            "magneto", inclination_deg=90.0, yaw_deg=yaw, leg_order=order, seconds=seconds
        )
        stepped = Climb.from_scenario(scenario).leg_order  # what the robot did
        rollout = simulate(scenario)
        assert rollout.attached, rollout.failure
        arrays = {k: np.asarray(v)[first:] for k, v in rollout.arrays.items()}
        columns = flatten(arrays, 4)
        file = f"climb-{name}.parquet"
        pq.write_table(
            pa.table(columns),
            FOLDER / file,
            compression="zstd",
            use_dictionary=False,
            use_byte_stream_split=[n for n, c in columns.items() if c.dtype == np.float64],
        )
        entries.append(
            {
                "file": file,
                "scenario": {
                    "inclination_deg": 90,
                    "heading_deg": 0,
                    "yaw_deg": yaw,
                    "leg_order": list(stepped),
                },
            }
        )
    manifest = {
        "robot": "magneto",
        "record_period_s": 0.006,
        "source": "symbench's generator, leg orders as stepped (make_log.py)",
        "license": "CC0-1.0",
        "notes": "the data-symmetry tests: image pairs by leg order, one counterpart out of phase",
        "trajectories": entries,
    }
    (FOLDER / "import.json").write_text(json.dumps(manifest, indent=2) + "\n")
    print(f"wrote {len(entries)} logs to {FOLDER}")


if __name__ == "__main__":
    np.seterr(all="raise")
    main()

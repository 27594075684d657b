"""Make the small log of the worked example (docs/data-format.md, "A worked example"):
magneto climbing a wall at four slope headings, as another tool would log it.

    python tests/data/importing/logs/make_log.py   # rewrites magneto-wall/ beside it

Eight 0.3 s climbs (headings 0, 90, 180, 270, initial yaws 0 and 90), simulated by symbench's
own generator but written the way a robot's logger might: every 3 ms (twice as often as the
6 ms record period), positions, velocities and torques plus the contact and magnet flags, no
accelerations, and the base velocities in the base frame. `symbench data import` derives the
accelerations, rotates the velocities into the world frame and decimates to 6 ms.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pyarrow as pa
import pyarrow.parquet as pq

from symbench.core.data.importing.derive import world_to_body
from symbench.core.data.storage.columns import flatten
from symbench.core.sim.climb.rollout import simulate
from symbench.core.sim.scene.scenario import Scenario

FOLDER = Path(__file__).parent / "magneto-wall"
PERIOD = 0.003
HEADINGS = (0.0, 90.0, 180.0, 270.0)
YAWS = (0.0, 90.0)
SECONDS = 0.3
KEPT = ("t", "base_pos", "base_quat", "base_linvel", "base_angvel", "q", "qd", "tau")


def main() -> None:
    FOLDER.mkdir(parents=True, exist_ok=True)
    entries = []
    for heading in HEADINGS:
        for yaw in YAWS:
            scenario = Scenario(
                "magneto", inclination_deg=90.0, heading_deg=heading, yaw_deg=yaw, seconds=SECONDS
            )
            rollout = simulate(scenario, record_period=PERIOD)
            assert rollout.attached, rollout.failure
            arrays = world_to_body(rollout.arrays)
            columns = {
                name: values
                for name, values in flatten(arrays, 4).items()
                if name.split(".")[0] in KEPT or name.split(".")[0] in ("contact", "magnet")
            }
            name = f"climb-h{heading:03.0f}-y{yaw:02.0f}.parquet"
            pq.write_table(
                pa.table(columns),
                FOLDER / name,
                compression="zstd",
                use_dictionary=False,
                use_byte_stream_split=[n for n, c in columns.items() if c.dtype == np.float64],
            )
            entries.append(
                {
                    "file": name,
                    "scenario": {"inclination_deg": 90, "heading_deg": heading, "yaw_deg": yaw},
                }
            )
    manifest = {
        "robot": "magneto",
        "record_period_s": PERIOD,
        "base_frame": "body",
        "source": "symbench's generator, logged at 3 ms without accelerations (make_log.py)",
        "license": "CC0-1.0",
        "notes": "the worked example of docs/data-format.md",
        "trajectories": entries,
    }
    (FOLDER / "import.json").write_text(json.dumps(manifest, indent=2) + "\n")
    print(f"wrote {len(entries)} logs to {FOLDER}")


if __name__ == "__main__":
    np.seterr(all="raise")
    main()

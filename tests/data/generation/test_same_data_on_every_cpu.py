"""The standard datasets are byte-identical on every x86-64 CPU.

The smoke datasets of all three robots are regenerated and compared with the content hashes
committed in `symbench.core.data.generation.reference_hashes` (made on another machine), once with
this process as it is and once from a `symbench` process forced onto other CPU kernels (OpenBLAS,
numpy's SIMD loops, glibc's libm, pyarrow): the generator's workers pin their own numerics,
so neither the CPU nor the caller's environment may change a bit. A machine whose CPU picks
other kernels than the one the hashes were made on therefore fails here, whatever that CPU
is.

After a deliberate change to the data (bump DATASET_VERSION) or to a pinned library
version, regenerate and update `reference_hashes` with the printed hashes.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

from symbench.core.common.errors import SymbenchError
from symbench.core.config.presets import dataset_id
from symbench.core.data.generation.determinism import numerics_problems, pinned_environment
from symbench.core.data.generation.reference_hashes import LIBRARY_VERSIONS, reference_hash
from symbench.core.data.storage.metadata import library_versions

ROBOTS = ("magneto", "hexa", "nona")
OTHER_KERNELS = {
    "OPENBLAS_CORETYPE": "Sandybridge",  # FMA-free AVX kernels, unlike both the pin and default
    "OPENBLAS_NUM_THREADS": "2",
    "NPY_DISABLE_CPU_FEATURES": pinned_environment()["NPY_DISABLE_CPU_FEATURES"],  # baseline loops
    "GLIBC_TUNABLES": "glibc.cpu.hwcaps=-AVX2",
    "ARROW_USER_SIMD_LEVEL": "AVX2",
}


def _expected(robot: str, preset: str = "smoke") -> str:
    did = dataset_id(robot, preset)
    assert library_versions() == LIBRARY_VERSIONS, "the installed libraries are not the pinned ones"
    expected = reference_hash(did, LIBRARY_VERSIONS)
    assert expected, f"no reference hash for {did}: regenerate and add it"
    return expected


# smoke@v6: the previous version's grid still regenerates bit for bit (the published v6
# board's data), so a change to the simulator that moves old data fails here too
# the current generator by default; the archived v6 one's hashes under -m slow
@pytest.mark.parametrize("preset", ["smoke", pytest.param("smoke@v6", marks=pytest.mark.slow)])
@pytest.mark.parametrize("robot", ROBOTS)
def test_smoke_dataset_matches_the_committed_hash(robot, preset, tmp_path, monkeypatch):
    from symbench.core.data.generation.generate import generate

    monkeypatch.setenv("SYMBENCH_HOME", str(tmp_path))
    report = generate(robot, preset, workers=1, show_progress=False)
    assert report.content_hash == _expected(robot, preset), (
        f"{report.dataset_id} has hash {report.content_hash} on this CPU"
    )


# hexa by default (every robot's hash on this CPU: above); the others under -m slow
@pytest.mark.parametrize(
    "robot", ["hexa", *(pytest.param(r, marks=pytest.mark.slow) for r in ("magneto", "nona"))]
)
def test_smoke_dataset_matches_from_a_caller_on_other_kernels(robot, tmp_path):
    env = {**os.environ, **OTHER_KERNELS, "SYMBENCH_HOME": str(tmp_path), "MUJOCO_GL": "disable"}
    cli = Path(sys.executable).with_name("symbench")
    out = subprocess.run(
        [
            str(cli),
            "data",
            "generate",
            "--robot",
            robot,
            "--preset",
            "smoke",
            "--workers",
            "2",
            "--no-progress",
        ],
        env=env,
        capture_output=True,
        text=True,
        timeout=600,
    )
    assert out.returncode == 0, out.stderr
    printed = out.stdout.replace("\n", " ")
    assert f"content hash {_expected(robot)}" in printed, out.stdout
    assert "matches the reference hash committed with symbench" in printed


def test_the_real_simulator_refuses_unpinned_numerics(tmp_path, monkeypatch):
    """The guard, not a convention: simulating a dataset here, unpinned, is an error."""
    from symbench.core.data.generation import generate as generation
    from symbench.core.sim.scene.scenario import Scenario

    for name in pinned_environment():
        monkeypatch.delenv(name, raising=False)
    assert numerics_problems(), "this test process should not be pinned"
    task = generation.Task(
        0,
        Scenario(robot="hexa", seconds=0.05).to_dict(),
        tmp_path,
        6,
        {"record_period_s": 0.006},
        generation.default_simulator(),
    )
    with pytest.raises(
        SymbenchError, match="refusing to generate data with CPU-dependent numerics"
    ):
        generation.run_task(task)
    assert not (tmp_path / "records").exists()

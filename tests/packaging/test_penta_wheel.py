"""Adding a robot stays a tested path: the example robot plugin `examples/symbench-penta/`
(a five-legged climber, group C5), built as a wheel (not editable) and installed with
symbench's wheel into a fresh virtual environment outside the repository, ships its spec as
package data, loads, passes its own tests with symbench's kit, verifies its symmetry in
simulation, and goes through a smoke dataset and a smoke run."""

from __future__ import annotations

import json
import zipfile
from pathlib import Path

import pytest
from fresh_env import ROOT, FreshEnv, build_wheel, run

PENTA = ROOT / "examples" / "symbench-penta"


class Penta(FreshEnv):
    def __init__(self, tmp: Path, symbench_wheel: Path) -> None:
        self.source, self.wheel = build_wheel(PENTA, tmp, "symbench-penta")
        super().__init__(tmp, [symbench_wheel, self.wheel])


@pytest.fixture(scope="module")
def penta(tmp_path_factory, symbench_wheel) -> Penta:
    return Penta(tmp_path_factory.mktemp("penta"), symbench_wheel[1])


def test_the_wheel_ships_the_robot_as_package_data(penta):
    names = set(zipfile.ZipFile(penta.wheel).namelist())
    assert {"symbench_penta/penta/robot.toml", "symbench_penta/penta/README.md"} <= names
    entry_points = next(n for n in names if n.endswith(".dist-info/entry_points.txt"))
    text = zipfile.ZipFile(penta.wheel).read(entry_points).decode()
    assert "[symbench]" in text and "penta = symbench_penta" in text


def test_the_installed_robot_loads_from_the_fresh_environment(penta):
    listed = {r["name"]: r for r in json.loads(penta.symbench("list", "robots", "--json").stdout)}
    assert set(listed) == {"hexa", "magneto", "nona", "penta"}
    spec_dir = Path(listed["penta"]["spec_dir"])
    assert spec_dir == penta.site / "symbench_penta" / "penta"
    assert (spec_dir / "robot.toml").is_file()
    code = "from symbench import load_robot; s = load_robot('penta'); print(s.n_legs, s.group)"
    assert run([penta.python, "-c", code], penta.tmp, penta.env).stdout.split()[0] == "5"


def test_the_plugin_passes_its_own_tests(penta):
    """The example's tests, with symbench's pytest plugin (the kit's fixtures) from the wheel."""
    tests = penta.source / "tests"
    result = run(
        [penta.python, "-m", "pytest", "-q", "-p", "no:cacheprovider", "-o", "addopts=", tests],
        penta.tmp,
        penta.env,
    )
    assert "3 passed" in result.stdout


@pytest.mark.slow  # minutes on 2 cores: kept out of the default suite's 10
def test_sim_check_verifies_the_climb_and_the_d5_symmetry(penta):
    """The declared C5 rotation and the mirror the geometry has (D5), both simulated."""
    report = json.loads(
        penta.symbench("sim", "check", "--robot", "penta", "--seconds", "1", "--json").stdout
    )
    assert report["attached"] and report["scenario"]["robot"] == "penta"
    symmetry = report["symmetry"]
    generators = [(g["generator"], g["declared"]) for g in symmetry["generators"]]
    assert symmetry["symmetric"] and generators == [("shift 1", True), ("mirror 0", False)]
    assert symmetry["groups"] == "C5 declared, D5 from geometry"  # the group it verified
    assert all(g["error"] < 1e-9 for g in symmetry["generators"])


@pytest.mark.slow  # minutes on 2 cores: kept out of the default suite's 10
def test_a_smoke_dataset_and_a_smoke_run(penta):
    generated = penta.symbench(
        "data", "generate", "--robot", "penta", "--preset", "smoke", "--no-progress", timeout=600
    )
    printed = " ".join(generated.stdout.split())  # no reference hash: expected, and said so
    assert "no reference hash for this id: expected for a plugin robot's dataset" in printed
    out = penta.tmp / "results"
    penta.symbench(
        "run",
        "--model",
        "sdnn",
        "--robot",
        "penta",
        "--preset",
        "smoke",
        "--max-steps",
        "20",
        "--output",
        str(out),
        timeout=600,
    )
    (record,) = out.glob("penta-*.json")
    data = json.loads(record.read_text())
    assert "penta" in json.dumps(data)
    assert data["robot_plugin"] == {
        "plugin": "penta",
        "distribution": "symbench-penta",
        "version": "0.1.0",
    }

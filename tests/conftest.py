"""Builders shared by all tests, and the Hypothesis profiles of the property suite
(tests/properties): a bounded number of examples per property in the default suite, many more
under `-m slow`, which selects the same properties again.

    pytest tests/properties              # DEFAULT_EXAMPLES each
    pytest tests/properties -m slow      # SLOW_EXAMPLES each
"""

from __future__ import annotations

import contextlib
import os
import shutil
from pathlib import Path

import pytest
from filelock import FileLock
from hypothesis import HealthCheck, settings
from synthetic_raw import fake_simulate

from symbench.core.config.presets import dataset_id
from symbench.core.config.provenance import hardware, library_versions
from symbench.core.data.generation.generate import ensure_dataset, generate
from symbench.core.sim.scene.scenario import Scenario

HASH = "ab" * 32
DEFAULT_EXAMPLES = 50
SLOW_EXAMPLES = 500
PROPERTIES = Path(__file__).parent / "properties"

for _name, _examples in (("symbench-default", DEFAULT_EXAMPLES), ("symbench-slow", SLOW_EXAMPLES)):
    # no deadline: examples write files, and the machine may be busy
    settings.register_profile(
        _name, max_examples=_examples, deadline=None, suppress_health_check=[HealthCheck.too_slow]
    )


def _slow_run(config: pytest.Config) -> bool:
    """Whether `-m` selects the slow tests (the default `-m 'not slow'` does not)."""
    expression = config.getoption("markexpr") or ""
    return "slow" in expression and "not slow" not in expression


def pytest_configure(config: pytest.Config) -> None:
    settings.load_profile("symbench-slow" if _slow_run(config) else "symbench-default")


@pytest.hookimpl(tryfirst=True)  # before `-m` deselects by marker
def pytest_collection_modifyitems(config: pytest.Config, items: list[pytest.Item]) -> None:
    if _slow_run(config):
        for item in items:
            if item.path.is_relative_to(PROPERTIES):
                item.add_marker(pytest.mark.slow)


def record_dict(
    robot: str = "hexa",
    split: str = "iid",
    model: str = "sdnn",
    backend: str = "torch",
    seed: int = 0,
    rmse: float = 0.1,
    content_hash: str = HASH,
) -> dict:
    """A complete, valid (unsealed: `write_record` seals it) result record with the given
    identity and RMSE."""
    return {
        "schema_version": 2,
        "created": "2026-11-22T00:00:00Z",
        "model": {
            "name": model,
            "backend": backend,
            "view": "leg_grouped",
            "variant": "acc",
            "equivariant": True,
            "hyperparameters": {"latent": 128},
            "learning_rate": 5e-4,
            "parameters": 1234,
            "plugin": {
                "module": "symbench.plugins.torch_models.sdnn",
                "distribution": "symbench",
                "version": "0.1.0",
                "source_sha256": "12" * 32,
            },
        },
        "robot": robot,
        "dataset": {
            "id": dataset_id(robot, "smoke"),
            "content_hash": content_hash,
            "robot_spec_hash": "cd" * 32,
            "preset": "smoke",
        },
        "split": split,
        "seed": seed,
        "samples": {
            "train": 10,
            "val": 2,
            "test": 3,
            "train_trajectories": 2,
            "val_trajectories": 1,
            "test_trajectories": 1,
        },
        "training": {
            "epochs": 3,
            "best_epoch": 2,
            "stopped_early": False,
            "best_val_loss": 0.5,
            "batch_size": 64,
            "config": {
                "seed": seed,
                "batch_size": 64,
                "max_epochs": 3,
                "stop_ratio": 0.7,
                "stop_patience": 5,
                "learning_rate": 5e-4,
                "hyper": {},
                "compile": False,
            },
            "checkpoint_sha256": {"model.safetensors": "34" * 32},
        },
        "metrics": {"torque-error": {"rmse": rmse, "nrmse": rmse / 2}},
        "timings_s": {"train": 1.0},
        "hardware": hardware(),
        "versions": library_versions(),
        "git_commit": "0" * 40,
    }


@pytest.fixture
def home(tmp_path, monkeypatch):
    """A private, empty $SYMBENCH_HOME for one test."""
    monkeypatch.setenv("SYMBENCH_HOME", str(tmp_path / "home"))
    return tmp_path / "home"


@pytest.fixture
def smoke_hexa(home):
    """hexa's smoke dataset in `home`, simulated by the stand-in: the same files and id as the
    real one, in a fraction of a second."""
    return generate("hexa", "smoke", simulator=fake_simulate, show_progress=False)


SMOKE_ROBOTS = ("magneto", "hexa", "nona")


@pytest.fixture(scope="session")
def real_smoke_home(tmp_path_factory) -> Path:
    """A home holding every built-in robot's smoke dataset simulated for real (about 30 s),
    made once per test run: under xdist the first worker to ask makes it, under a lock in the
    run's folder, and the others wait for it. Read only: a test gets a copy (`real_smoke_copy`)."""
    root = tmp_path_factory.getbasetemp()
    if os.environ.get("PYTEST_XDIST_WORKER"):
        root = root.parent  # this run's folder, which its workers share
    home = root / "real-smoke-home"
    with FileLock(f"{home}.lock"):
        if not (root / "real-smoke-home.complete").exists():
            with pytest.MonkeyPatch.context() as patch:
                patch.setenv("SYMBENCH_HOME", str(home))
                for robot in SMOKE_ROBOTS:
                    ensure_dataset(robot, "smoke", workers=1, show_progress=False)
            (root / "real-smoke-home.complete").touch()
    return home


@pytest.fixture(scope="session")
def real_smoke_copy(real_smoke_home, tmp_path_factory):
    """`with real_smoke_copy(name) as home:` a private copy of `real_smoke_home` as
    $SYMBENCH_HOME for the block, for tests that may write into their home."""

    @contextlib.contextmanager
    def copy(name: str):
        home = Path(shutil.copytree(real_smoke_home, tmp_path_factory.mktemp(name) / "home"))
        with pytest.MonkeyPatch.context() as patch:
            patch.setenv("SYMBENCH_HOME", str(home))
            yield home

    return copy


@pytest.fixture(scope="session")
def simulated_smoke_hexa(real_smoke_copy):
    """hexa's smoke dataset, simulated for real, in a private home: its rotated and
    heading-turned climbs are exact images, which the stand-in's are not."""
    from symbench.core.data.dataset import load_dataset

    with real_smoke_copy("simulated"):
        yield load_dataset(dataset_id("hexa", "smoke"))


# hexa climbs drawn as v7 draws them (yaw, heading, slope and direction continuous, each
# step's swing its own), short: no two are rotated images of each other
DRAWN = tuple(
    Scenario("hexa", slope, heading, yaw, direction, None, seed, 0.4, gait_spread=0.2)
    for slope, heading, yaw, direction, seed in (
        (62.5, 31.25, 12.75, 23.5, 3),
        (118.0, 201.5, 101.25, 291.0, 4),
        (90.5, 144.0, 247.5, 147.25, 5),
    )
)


@pytest.fixture(scope="session")
def drawn_hexa_home(tmp_path_factory):
    """A private home holding `hexa-drawn`, the DRAWN climbs simulated for real (seconds)."""
    home = tmp_path_factory.mktemp("drawn") / "home"
    with pytest.MonkeyPatch.context() as patch:
        patch.setenv("SYMBENCH_HOME", str(home))
        generate("hexa", "smoke", show_progress=False, scenarios=DRAWN, id_override="hexa-drawn")
    return home


@pytest.fixture
def drawn_hexa(drawn_hexa_home, monkeypatch):
    """`hexa-drawn`, loaded with its home as this test's $SYMBENCH_HOME."""
    from symbench.core.data.dataset import load_dataset

    monkeypatch.setenv("SYMBENCH_HOME", str(drawn_hexa_home))
    return load_dataset("hexa-drawn")


@pytest.fixture(scope="session")
def make_record():
    return record_dict


def schema_1(record: dict) -> dict:
    """The record as schema 1 wrote it: unsealed, without provenance."""
    record["schema_version"] = 1
    del record["model"]["plugin"]
    for field in ("config", "checkpoint_sha256"):
        del record["training"][field]
    return record


@pytest.fixture(scope="session")
def as_schema_1():
    return schema_1

"""Image pairs made on purpose, for datasets that hold none: `symbench data symmetry ID
--twins N` and the data-symmetry evaluator.

Climbs drawn from continuous distributions (dataset v7) are never rotated images of each
other, so `pair_up` finds nothing to compare. A generated dataset stores the simulator's
input, though, so its climbs can be simulated again turned: N of its climbs, evenly spaced
over its trajectories, each once more with the yaw grown by one symmetry step (360 /
rotation order degrees) and every other field kept. The simulator carries the direction and
leg order along with the base (`scenario_gait`), and the seed, hence the start perturbation
and every step's swing draws (`Climb.step_draws`), stays: the twin is `Climb.turned(1)` of
the original, which `pair_up` reads as its image. The originals are simulated again beside
their twins, so that both of a pair come from this simulator; the 2N climbs are a dataset of
their own in the cache, `<ID>-twins<N>`, generated (and resumed, and reused) like any.
"""

from __future__ import annotations

from dataclasses import replace
from typing import Any

from symbench.core.common.errors import SymbenchError
from symbench.core.data.dataset import Dataset, load_dataset
from symbench.core.data.storage.metadata import METADATA, dataset_dir, library_versions
from symbench.core.data.symmetry.report import SymmetryReport, Twins, dataset_symmetry
from symbench.core.sim.scene.scenario import Scenario


def twins_id(dataset: Dataset, n: int) -> str:
    return f"{dataset.id}-twins{n}"


def chosen(dataset: Dataset, n: int) -> list[dict[str, Any]]:
    """The trajectory records of the `n` climbs to turn: evenly spaced over the dataset's."""
    records = dataset.metadata["trajectories"]
    if dataset.metadata.get("source") != "generated":
        raise SymbenchError(
            f"dataset '{dataset.id}' is imported: its climbs cannot be simulated again turned"
        )
    if not 1 <= n <= len(records):
        raise SymbenchError(
            f"--twins takes 1 to {len(records)} climbs of dataset '{dataset.id}', got {n}"
        )
    return [records[i * len(records) // n] for i in range(n)]


def twin_scenarios(dataset: Dataset, n: int) -> list[Scenario]:
    """Each chosen climb's scenario, followed by its twin's: the yaw one step further."""
    step = dataset.spec.symmetry_angle_deg
    out = []
    for record in chosen(dataset, n):
        original = Scenario.from_dict(record["scenario"])
        out += [original, replace(original, yaw_deg=(original.yaw_deg + step) % 360.0)]
    return out


def twins_dataset(
    dataset: Dataset, n: int, workers: int = 2, show_progress: bool = False
) -> Dataset:
    """The derived dataset of `n` climbs of `dataset` and their twins: the cached one when it
    is what generating it would make, else generated (resuming a partial one)."""
    from symbench.core.data.generation.generate import generate

    did = twins_id(dataset, n)
    scenarios = twin_scenarios(dataset, n)
    expected = [s.to_dict() for s in scenarios]
    if (dataset_dir(did) / METADATA).is_file():
        try:
            cached = load_dataset(did)
        except SymbenchError:  # damaged or all failed: generate() mends what it must
            cached = None
        if cached is not None and _holds(cached, expected, dataset.spec.spec_hash()):
            return cached
    generate(
        dataset.robot,
        dataset.metadata["preset"],
        workers,
        show_progress=show_progress,
        scenarios=scenarios,
        id_override=did,
        repair_command=f"symbench data symmetry {dataset.id} --twins {n}",
    )
    return load_dataset(did)


def _holds(cached: Dataset, expected: list[dict[str, Any]], spec_hash: str) -> bool:
    """Whether the cached derived dataset is what generating it now would make: these
    scenarios, this robot spec and these library versions (its files are verified)."""
    meta = cached.metadata
    records = sorted(meta["trajectories"] + meta["failures"], key=lambda r: r["id"])
    return (
        meta["robot_spec_hash"] == spec_hash
        and meta["versions"] == library_versions()
        and [r["scenario"] for r in records] == expected
    )


def twin_symmetry(
    dataset: Dataset, n: int, workers: int = 2, show_progress: bool = False
) -> SymmetryReport:
    """The symmetry report of `n` pairs constructed from `dataset` (see the module)."""
    derived = twins_dataset(dataset, n, workers, show_progress)
    report = dataset_symmetry(derived)
    source_sha = {r["id"]: r["sha256"] for r in dataset.metadata["trajectories"]}
    made_sha = {r["id"]: r["sha256"] for r in derived.metadata["trajectories"]}
    reproduced = all(
        made_sha.get(2 * k) == source_sha[r["id"]] for k, r in enumerate(chosen(dataset, n))
    )
    report.constructed = Twins(
        dataset.id, derived.id, n, dataset.spec.symmetry_angle_deg, reproduced
    )
    return report

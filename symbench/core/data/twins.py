"""Image pairs made on purpose, for datasets that hold none: `symbench data symmetry ID`
(`--twins N`) and the data-symmetry evaluator.

Climbs drawn from continuous distributions (dataset v7) are never rotated images of each
other, so `pair_up` finds nothing to compare. A generated dataset stores the simulator's
input, though, so its climbs can be simulated again turned: N of its climbs, evenly spaced
over its trajectories (a deterministic sample; v7's climbs are each drawn at random from
their own seed already), each once more under every rotation of the robot's group, the
yaw grown by k symmetry steps (k x 360 / rotation order degrees, k = 1 ... order - 1) and
every other field kept. The simulator carries the direction and leg order along with the base
(`scenario_gait`), and the seed, hence the start perturbation and every step's swing draws
(`Climb.step_draws`), stays: each twin is `Climb.turned(k)` of the original, which
`pair_up` reads as its image under the k-th rotation (the twins among themselves pair too).
Mirrors are not constructed (pairing reads none from scenarios). The originals are
simulated again beside their twins, so that both of a pair come from this simulator; the
N x order climbs are a dataset of their own in the cache, `<ID>-twins<N>`, generated (and
resumed, and reused) like any.
"""

from __future__ import annotations

from dataclasses import replace
from typing import Any

from symbench.core.common.errors import SymbenchError
from symbench.core.data.dataset import Dataset, load_dataset
from symbench.core.data.storage.metadata import METADATA, dataset_dir, library_versions
from symbench.core.data.symmetry.report import (
    NoImagePairsError,
    SymmetryReport,
    Twins,
    dataset_symmetry,
)
from symbench.core.sim.scene.scenario import Scenario

DEFAULT_TWINS = 8  # climbs simulated again when a generated dataset holds no image pairs


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


def _order(dataset: Dataset) -> int:
    """The rotation order of the dataset's group: its climbs and their twins per original."""
    group = dataset.spec.group
    if group.rotation_order < 2:
        raise SymbenchError(
            f"robot '{dataset.robot}' declares no rotation (group {group.name}): "
            "there is no rotated image of a climb to construct"
        )
    return group.rotation_order


def twin_scenarios(dataset: Dataset, n: int) -> list[Scenario]:
    """Each chosen climb's scenario, followed by its twins': the yaw 1, 2, ... order - 1
    symmetry steps further."""
    step, order = dataset.spec.symmetry_angle_deg, _order(dataset)
    out = []
    for record in chosen(dataset, n):
        original = Scenario.from_dict(record["scenario"])
        out += [
            replace(original, yaw_deg=(original.yaw_deg + k * step) % 360.0) if k else original
            for k in range(order)
        ]
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
    dataset: Dataset,
    n: int,
    workers: int = 2,
    show_progress: bool = False,
    found_none: bool = False,
) -> SymmetryReport:
    """The symmetry report of the pairs constructed from `n` climbs of `dataset` (see the
    module); `found_none` says that the dataset itself holds no image pair (else they were
    asked for)."""
    derived = twins_dataset(dataset, n, workers, show_progress)
    report = dataset_symmetry(derived)
    order = _order(dataset)
    source_sha = {r["id"]: r["sha256"] for r in dataset.metadata["trajectories"]}
    made_sha = {r["id"]: r["sha256"] for r in derived.metadata["trajectories"]}
    reproduced = all(
        made_sha.get(order * k) == source_sha[r["id"]] for k, r in enumerate(chosen(dataset, n))
    )
    report.constructed = Twins(
        dataset.id,
        derived.id,
        n,
        len(dataset.metadata["trajectories"]),
        dataset.spec.symmetry_angle_deg,
        order - 1,
        reproduced,
        found_none,
    )
    return report


def symmetry_report(
    dataset: Dataset, twins: int | None = None, workers: int = 2, show_progress: bool = False
) -> SymmetryReport:
    """What `symbench data symmetry` reports: the image pairs `dataset` holds; pairs
    constructed from `twins` of its climbs when asked; and, when a generated dataset holds
    none (v7's drawn climbs), pairs constructed from `DEFAULT_TWINS` of them (all, if fewer),
    the report saying so. An imported dataset without pairs is a `NoImagePairsError`."""
    if twins is not None:
        return twin_symmetry(dataset, twins, workers, show_progress)
    try:
        return dataset_symmetry(dataset)
    except NoImagePairsError:
        if dataset.metadata.get("source") != "generated":
            raise
    n = min(DEFAULT_TWINS, len(dataset.metadata["trajectories"]))
    return twin_symmetry(dataset, n, workers, show_progress, found_none=True)

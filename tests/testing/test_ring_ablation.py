"""sdnn with `ring` 1 (each leg also sees its two neighbours): equivariant to each robot's
rotations, and to nothing more than the cyclic shifts of its legs, where plain sdnn is
equivariant to every permutation; the ablation of that over-constraint on the board."""

from __future__ import annotations

import pytest

from symbench.core.common.errors import SymbenchError
from symbench.core.data.views.frames import LegFrames
from symbench.core.plugin import registry
from symbench.core.robot.specs import load_robot
from symbench.testing.equivariance import check_model
from symbench.testing.model_group import measure_symmetry_group

ROTATIONS = {"magneto": "C2", "hexa": "C6", "nona": "C9"}


# every robot in torch; JAX on hexa by default (its compiles: seconds each), all under -m slow
@pytest.mark.parametrize(
    ("robot", "backend"),
    [
        *((r, "torch") for r in ROTATIONS),
        ("hexa", "jax"),
        *(pytest.param(r, "jax", marks=pytest.mark.slow) for r in ("magneto", "nona")),
    ],
)
def test_the_ring_model_is_equivariant_to_the_robots_rotations(robot, backend):
    spec = load_robot(robot)
    report = check_model(
        registry.model("sdnn", backend),
        spec.group,
        frames=LegFrames.from_spec(spec),
        hyper={"ring": 1},
    )
    assert report.group == ROTATIONS[robot]
    assert report.equivariant and report.controls_failed


@pytest.mark.parametrize(("robot", "order", "plain"), [("magneto", 4, 24), ("hexa", 6, 720)])
def test_the_ring_narrows_the_models_group_to_the_cyclic_shifts(robot, order, plain):
    """Every permutation of the legs is tried (up to 6 legs): plain sdnn keeps all of them,
    the ring model only the n cyclic shifts (for hexa exactly its robot's group)."""
    entry = registry.model("sdnn", "torch")
    ring = measure_symmetry_group(entry, robot, hyper={"ring": 1})
    assert ring.exhaustive and ring.contains_robot_group
    n = load_robot(robot).n_legs
    shifts = {tuple((i + s) % n for i in range(n)) for s in range(n)}
    assert set(ring.equivariant_to) == shifts and ring.order == order
    assert measure_symmetry_group(entry, robot).order == plain
    assert ring.to_dict()["over_constrained"] is (robot == "magneto")  # C4 > C2


def test_ring_and_mirror_are_not_combined():
    entry = registry.model("sdnn", "torch")
    spec = load_robot("hexa")
    with pytest.raises(SymbenchError, match="ring and mirror cannot be combined"):
        check_model(
            entry, spec.group, frames=LegFrames.from_spec(spec), hyper={"ring": 1, "mirror": 1}
        )

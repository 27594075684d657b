"""Views: shapes and names, gravity-axis invariance, and view(g . raw) == g . view(raw)."""

from __future__ import annotations

import numpy as np
import pytest
from synthetic_raw import synthetic_raw

from symbench.core.common.errors import SymbenchError
from symbench.core.data.symmetry.raw_action import act_on_raw, base_map, rotate_scene_about_gravity
from symbench.core.data.views import schema
from symbench.core.data.views.frames import LegFrames
from symbench.core.data.views.transforms import build_view, sample_rows
from symbench.core.robot.specs import load_robot
from symbench.core.symmetry.groups import GroupElement, act

ROBOTS = ("magneto", "hexa", "nona")
VARIANTS = ("acc", "next")


def _two_trajectories(n_legs: int) -> tuple[dict, np.ndarray]:
    a, b = synthetic_raw(n_legs, 40, seed=1), synthetic_raw(n_legs, 25, seed=2)
    raw = {k: np.concatenate([a[k], b[k]]) for k in a}
    return raw, np.repeat([3, 7], [40, 25])


@pytest.mark.parametrize("robot", ROBOTS)
@pytest.mark.parametrize("variant", VARIANTS)
def test_leg_grouped_is_equivariant_under_every_group_element(robot, variant):
    spec = load_robot(robot)
    frames = LegFrames.from_spec(spec)
    raw, traj = _two_trajectories(spec.n_legs)
    layout = schema.leg_grouped_input(variant)
    base = build_view(raw, traj, frames, "leg_grouped", variant)
    assert spec.group.order > 1
    for g in spec.group:
        moved = build_view(act_on_raw(g, raw, frames), traj, frames, "leg_grouped", variant)
        want_x = spec.group.act(g, base.inputs["x"], layout.reflection_signs)
        want_y = spec.group.act(g, base.target, schema.TARGET.reflection_signs)
        np.testing.assert_allclose(moved.inputs["x"], want_x, atol=1e-10, rtol=0)
        np.testing.assert_allclose(moved.target, want_y, atol=1e-10, rtol=0)
        if g != spec.group.identity:  # the action does something: the data are not symmetric
            assert np.abs(moved.inputs["x"] - base.inputs["x"]).max() > 1e-3


@pytest.mark.parametrize("robot", ROBOTS)
def test_reflections_act_on_raw_like_on_views(robot):
    """Dihedral elements (mirror + relabel) of the same legs: the raw mirror is right too."""
    spec = load_robot(robot)
    n = spec.n_legs
    frames = LegFrames.from_spec(spec)
    # a mirror maps leg i to leg (offset - i); find the offsets the geometry allows
    raw, traj = _two_trajectories(n)
    layout = schema.leg_grouped_input("next")
    tried = 0
    for offset in range(n):
        g = GroupElement(tuple((offset - i) % n for i in range(n)), True)
        try:
            base_map(frames, g)
        except SymbenchError:
            continue
        tried += 1
        base = build_view(raw, traj, frames, "leg_grouped", "next")
        moved = build_view(act_on_raw(g, raw, frames), traj, frames, "leg_grouped", "next")
        np.testing.assert_allclose(
            moved.inputs["x"], act(g, base.inputs["x"], layout.reflection_signs), atol=1e-10, rtol=0
        )
    assert tried > 0, f"no mirror fits {robot}'s leg frames"


def test_a_wrong_element_for_the_geometry_is_refused():
    frames = LegFrames.from_spec(load_robot("magneto"))
    with pytest.raises(SymbenchError, match="not symmetric"):
        base_map(frames, GroupElement((1, 2, 3, 0)))  # 90 degrees: magneto is not square


@pytest.mark.parametrize("variant", VARIANTS)
def test_leg_grouped_is_invariant_to_rotating_the_scene_about_gravity(variant):
    spec = load_robot("hexa")
    frames = LegFrames.from_spec(spec)
    raw, traj = _two_trajectories(spec.n_legs)
    base = build_view(raw, traj, frames, "leg_grouped", variant)
    for angle in (0.3, np.pi / 2, 2.0, -2.9):
        turned = rotate_scene_about_gravity(raw, angle)
        lg = build_view(turned, traj, frames, "leg_grouped", variant)
        np.testing.assert_allclose(lg.inputs["x"], base.inputs["x"], atol=1e-12, rtol=0)
        vec = build_view(turned, traj, frames, "vector", variant)
        vec0 = build_view(raw, traj, frames, "vector", variant)
        assert np.abs(vec.inputs["x"] - vec0.inputs["x"]).max() > 1e-2  # vector is not


@pytest.mark.parametrize("view", schema.VIEWS)
@pytest.mark.parametrize("variant", VARIANTS)
def test_views_keep_the_same_samples_and_name_their_columns(view, variant):
    spec = load_robot("nona")
    frames = LegFrames.from_spec(spec)
    raw, traj = _two_trajectories(spec.n_legs)
    v = build_view(raw, traj, frames, view, variant)
    assert len(v) == 40 - 1 + 25 - 1
    assert list(np.unique(v.trajectory)) == [3, 7]
    np.testing.assert_array_equal(v.target, raw["tau"][sample_rows(traj)])
    for key, a in v.inputs.items():
        assert a.shape[-1] == len(v.feature_names[key]), key
        assert a.dtype == np.float64 and np.all(np.isfinite(a))


def test_leg_grouped_columns_hold_what_they_say():
    spec = load_robot("hexa")
    frames = LegFrames.from_spec(spec)
    raw, traj = _two_trajectories(spec.n_legs)
    v = build_view(raw, traj, frames, "leg_grouped", "next")
    layout = schema.leg_grouped_input("next")
    rows = sample_rows(traj)
    x = v.inputs["x"]
    np.testing.assert_array_equal(layout.select(x, ["q_next"]), raw["q"][rows + 1])
    np.testing.assert_array_equal(layout.select(x, ["contact"])[..., 0], raw["contact"][rows])
    # gravity has norm 9.81 in every leg frame; p_i is minus the coxa origin, seen from leg i
    np.testing.assert_allclose(np.linalg.norm(layout.select(x, ["g"]), axis=-1), 9.81)
    p = layout.select(x, ["p"])[0]
    np.testing.assert_allclose(np.einsum("lij,lj->li", frames.rotations, p), -frames.origins)
    # with the base level and yaw 0, gravity in leg i is -9.81 z: leg z is the base z
    level = dict(raw, base_quat=np.tile([1.0, 0, 0, 0], (len(traj), 1)))
    acc = build_view(level, traj, frames, "leg_grouped", "acc").inputs["x"]
    g = schema.leg_grouped_input("acc").select(acc, ["g"])
    np.testing.assert_allclose(g, np.broadcast_to([0, 0, -9.81], g.shape), atol=1e-12)


def test_vector_and_graph_place_each_joint_where_their_names_say():
    spec = load_robot("magneto")
    frames = LegFrames.from_spec(spec)
    raw, traj = _two_trajectories(spec.n_legs)
    rows = sample_rows(traj)
    vec = build_view(raw, traj, frames, "vector", "acc")
    col = vec.feature_names["x"].index("leg2.qd.femur")
    np.testing.assert_array_equal(vec.inputs["x"][:, col], raw["qd"][rows, 2, 1])
    col = vec.feature_names["x"].index("base_quat.z")
    np.testing.assert_array_equal(vec.inputs["x"][:, col], raw["base_quat"][rows, 3])
    graph = build_view(raw, traj, frames, "body_graph", "next")
    layout = schema.body_graph(spec.n_legs, "next")
    edge = 3 * 1 + 2  # tibia of leg 1
    np.testing.assert_array_equal(graph.inputs["edges"][:, edge, 2], raw["q"][rows + 1, 1, 2])
    foot = layout.edges()[edge, 1]
    np.testing.assert_array_equal(graph.inputs["nodes"][:, foot, 2], raw["contact"][rows, 1])
    assert graph.inputs["nodes"][:, 0, 0].min() == 1.0


def test_unknown_view_names_the_known_ones():
    frames = LegFrames.from_spec(load_robot("hexa"))
    raw, traj = _two_trajectories(6)
    with pytest.raises(SymbenchError, match="leg_grouped"):
        build_view(raw, traj, frames, "leggrouped", "acc")

"""e2cnn-mlp's own tests, written with symbench's kit: the library's layers make the network
equivariant to the robot's rotations, on every built-in robot, and nothing more."""

from __future__ import annotations

import subprocess
import sys

import numpy as np
import pytest

from symbench import (
    Converge,
    ModelDims,
    ModelEntry,
    SymbenchError,
    TrainConfig,
    model_entry,
    schema,
    train,
)
from symbench.testing import BUILTIN_ROBOTS, check_model, measure_symmetry_group, synthetic_views

HEXA = ModelDims("leg_grouped", "acc", 6, (("x", (6, schema.leg_grouped_input("acc").size)),))


def hexa_inputs(n: int, dtype=np.float32) -> np.ndarray:
    return synthetic_views(6, n, seed=0)["leg_grouped"].inputs["x"].astype(dtype)


def entry() -> ModelEntry:
    return model_entry("e2cnn-mlp", "torch")  # found through the entry point


def mis_specified(dims: ModelDims, fields: int = 8, layers: int = 2, order: int = 0):
    """The same network with its input declared to turn like planar vectors (C_n's
    frequency-1 irreducible representation) where the legs carry the regular representation:
    a valid network for e2cnn, the wrong one for the robot. (Declaring the inputs trivial
    would be the plainer mistake, but e2cnn 0.2.3 cannot build a one-element basis on torch
    2.13: it masks with uint8.)"""
    from symbench_e2cnn.network import E2cnnMLP

    n_legs, n_features = dims.shape("x")
    return E2cnnMLP(n_legs, n_features, order, fields, layers, input_repr="irrep1")


@pytest.mark.parametrize("robot", BUILTIN_ROBOTS)
def test_equivariant_on_every_builtin_robot_in_float64_and_float32(symbench_kit, robot):
    report = symbench_kit.assert_equivariant(entry(), robot)  # every element, both dtypes
    assert report.max_error("float64") <= 1e-12 and report.max_error("float32") <= 1e-5


def test_equivariant_on_magneto_with_exactly_its_group(symbench_kit):
    report = symbench_kit.assert_equivariant(entry(), "magneto", hyper={"order": 2})
    assert report.group == "C2" and report.max_error("float64") <= 1e-12


def test_a_mis_specified_input_type_fails_the_kit():
    wrong = ModelEntry("e2cnn-mlp-wrong-input", "torch", "leg_grouped", "acc", True, mis_specified)
    report = check_model(wrong, "hexa")
    assert not report.equivariant and not report.passed
    assert report.max_error("float64") > 1e-2  # not rounding: the symmetry is gone


def test_a_smaller_group_passes_its_elements_only():
    report = check_model(entry(), "hexa", hyper={"order": 3, "fields": 8})  # C3 in hexa's C6
    held = {e.element for e in report.elements if e.errors["float64"] <= 1e-10}
    assert held == {"identity", "shift 2", "shift 4"}


def test_its_group_is_the_rotations_not_every_permutation():
    """sdnn is equivariant to all 720 permutations of hexa's legs; e2cnn-mlp to the 6
    rotations only (the library's C6)."""
    measured = measure_symmetry_group(entry(), "hexa", hyper={"fields": 8}, n_samples=4)
    assert measured.exhaustive and measured.order == 6
    assert set(measured.equivariant_to) == set(measured.robot_perms)


def test_an_order_that_does_not_divide_the_legs_is_refused():
    from symbench_e2cnn.network import rotation_order

    assert rotation_order(6, 0) == 6 and rotation_order(4, 2) == 2
    for order in (4, 1, -6):
        with pytest.raises(SymbenchError, match=f"order {order} is not a divisor of the robot's 6"):
            rotation_order(6, order)


def test_saved_parameters_are_the_library_coefficients_only():
    """No basis or cached filter in the state: checkpoints load into a fresh network, in any
    mode, and give the same torques."""
    import torch

    net = entry().build(HEXA, fields=8)
    assert all(k.endswith((".weights", ".bias")) for k in net.state_dict())
    keys = list(net.state_dict())
    net.eval()
    assert list(net.state_dict()) == keys
    fresh = entry().build(HEXA, fields=8)
    fresh.load_state_dict(net.state_dict())
    x = torch.from_numpy(hexa_inputs(16))
    with torch.no_grad():
        assert torch.equal(fresh.train()(x), net(x))


def test_converting_one_network_leaves_the_others_alone():
    """e2cnn shares a layer's basis between networks unless told not to: `.double()` on one
    network would then break every other float32 network of the process."""
    import torch

    a, b = entry().build(HEXA, fields=8), entry().build(HEXA, fields=8)
    a.double()
    with torch.no_grad():
        assert a(torch.from_numpy(hexa_inputs(4, np.float64))).dtype == torch.float64
        assert b(torch.from_numpy(hexa_inputs(4))).dtype == torch.float32


def test_e2cnn_mlp_learns():
    tr, va = synthetic_views(6, 512, seed=0), synthetic_views(6, 128, seed=1)
    model = train(
        entry(),
        tr["leg_grouped"],
        va["leg_grouped"],
        TrainConfig(
            schedule=Converge(max_steps=32, eval_every=8), hyper={"fields": 8}, progress=False
        ),
    )
    assert min(model.history["val_loss"][1:]) < model.history["val_loss"][0]


def test_registering_the_plugin_imports_neither_e2cnn_nor_torch():
    code = (
        "import sys\n"
        "from symbench import model_entry\n"
        "e = model_entry('e2cnn-mlp', 'torch')\n"
        "print(e.name, [m for m in ('e2cnn', 'torch') if m in sys.modules])"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "e2cnn-mlp []"

"""`fold_normalization`: the folded graph computes the same torques with four nodes fewer, and
a graph whose normalization feeds anything but linear layers is left as it was."""

from __future__ import annotations

import numpy as np
import onnx
import onnxruntime
import pytest
from onnx import TensorProto, helper, numpy_helper

from symbench.core.training.onnx_fold import fold_normalization

FEATURES, HIDDEN, OUT = 5, 7, 3


def normalized_mlp(also_to_relu: bool = False) -> onnx.ModelProto:
    """((x - mean) / std) -> MatMul + b -> Relu -> MatMul + b -> * scale + shift, as the
    torch export of a normalized network looks; with `also_to_relu` the normalized input
    also feeds a Relu, which no fold can absorb."""
    rng = np.random.default_rng(0)
    constants = {
        "mean": rng.normal(size=FEATURES),
        "std": rng.uniform(0.5, 2.0, size=FEATURES),
        "w0": rng.normal(size=(FEATURES, HIDDEN)),
        "b0": rng.normal(size=HIDDEN),
        "w1": rng.normal(size=(HIDDEN, OUT)),
        "b1": rng.normal(size=OUT),
        "scale": rng.uniform(0.5, 2.0, size=OUT),
        "shift": rng.normal(size=OUT),
    }
    nodes = [
        helper.make_node("Sub", ["x", "mean"], ["centred"]),
        helper.make_node("Div", ["centred", "std"], ["z"]),
        helper.make_node("MatMul", ["z", "w0"], ["h0"]),
        helper.make_node("Add", ["b0", "h0"], ["h1"]),  # the exporter puts the bias first
        helper.make_node("Relu", ["h1"], ["h2"]),
        helper.make_node("MatMul", ["h2", "w1"], ["o0"]),
        helper.make_node("Add", ["o0", "b1"], ["o1"]),
        helper.make_node("Mul", ["o1", "scale"], ["o2"]),
        helper.make_node("Add", ["o2", "shift"], ["torque"]),
    ]
    outputs = [helper.make_tensor_value_info("torque", TensorProto.FLOAT, [2, 4, OUT])]
    if also_to_relu:
        nodes.append(helper.make_node("Relu", ["z"], ["side"]))
        outputs.append(helper.make_tensor_value_info("side", TensorProto.FLOAT, [2, 4, FEATURES]))
    graph = helper.make_graph(
        nodes,
        "mlp",
        [helper.make_tensor_value_info("x", TensorProto.FLOAT, [2, 4, FEATURES])],
        outputs,
        [numpy_helper.from_array(v.astype(np.float32), k) for k, v in constants.items()],
    )
    return helper.make_model(graph, opset_imports=[helper.make_opsetid("", 17)])


def run(model: onnx.ModelProto, x: np.ndarray) -> np.ndarray:
    session = onnxruntime.InferenceSession(
        model.SerializeToString(), providers=["CPUExecutionProvider"]
    )
    return session.run(["torque"], {"x": x})[0]


def test_the_folded_graph_computes_the_same_with_four_nodes_fewer():
    model = normalized_mlp()
    x = np.random.default_rng(1).normal(size=(2, 4, FEATURES)).astype(np.float32)
    before = run(model, x)
    assert fold_normalization(model) == 2
    onnx.checker.check_model(model)
    assert [n.op_type for n in model.graph.node] == ["MatMul", "Add", "Relu", "MatMul", "Add"]
    np.testing.assert_allclose(run(model, x), before, rtol=1e-5, atol=1e-5)
    names = {t.name for t in model.graph.initializer}
    assert not names & {"mean", "std", "scale", "shift", "w0", "b0", "w1", "b1"}  # unused gone


def test_a_normalization_that_feeds_more_than_linear_layers_stays():
    model = normalized_mlp(also_to_relu=True)
    ops = [n.op_type for n in model.graph.node]
    assert fold_normalization(model) == 1  # the output side still folds
    assert [n.op_type for n in model.graph.node] == ops[:-3] + ops[-1:]


@pytest.mark.parametrize("shape", [(1,), (FEATURES, 1)])
def test_statistics_not_one_per_feature_are_left_alone(shape):
    model = normalized_mlp()
    for tensor in model.graph.initializer:
        if tensor.name == "mean":
            tensor.CopyFrom(numpy_helper.from_array(np.ones(shape, np.float32), "mean"))
    ops = [n.op_type for n in model.graph.node]
    assert fold_normalization(model) == 1
    assert [n.op_type for n in model.graph.node][:2] == ["Sub", "Div"] == ops[:2]

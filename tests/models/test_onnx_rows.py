"""`rows_first`: a batch-1 graph of per-leg layers runs on rows, computes the same torques
to float32 rounding in fewer nodes once ONNX Runtime has fused it, and any graph that a
dropped leading axis would change is left as it was."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import onnx
import onnxruntime
import pytest
from onnx import TensorProto, helper, numpy_helper

from symbench.core.training.onnx_rows import rows_first

LEGS, FEATURES, HIDDEN, OUT = 6, 5, 8, 3


def per_leg_network(batch: int = 1, sum_axis: int = 1, leg_bias: bool = False) -> onnx.ModelProto:
    """sdnn's shape in small: a per-leg layer, the sum over legs, a layer fed the leg and
    the sum (bias on the leg's product, as the torch export writes it), a ReLU, an output
    layer. `leg_bias` adds a constant of the batch's shape, (1, legs, out): on rows it would
    broadcast them back to three axes."""
    rng = np.random.default_rng(0)
    constants = {
        "w0": rng.normal(size=(FEATURES, HIDDEN)),
        "b0": rng.normal(size=HIDDEN),
        "w_leg": rng.normal(size=(HIDDEN, HIDDEN)),
        "w_sum": rng.normal(size=(HIDDEN, HIDDEN)),
        "b1": rng.normal(size=HIDDEN),
        "w2": rng.normal(size=(HIDDEN, OUT)),
        "b2": rng.normal(size=OUT),
        "per_leg": rng.normal(size=(1, LEGS, OUT)),
    }
    tensors = [numpy_helper.from_array(v.astype(np.float32), k) for k, v in constants.items()]
    tensors.append(numpy_helper.from_array(np.array([sum_axis], np.int64), "axes"))
    nodes = [
        helper.make_node("MatMul", ["x", "w0"], ["m0"]),
        helper.make_node("Add", ["b0", "m0"], ["a0"]),
        helper.make_node("Relu", ["a0"], ["h"]),
        helper.make_node("ReduceSum", ["h", "axes"], ["s"], keepdims=1),
        helper.make_node("MatMul", ["h", "w_leg"], ["m_leg"]),
        helper.make_node("Add", ["b1", "m_leg"], ["a_leg"]),
        helper.make_node("MatMul", ["s", "w_sum"], ["m_sum"]),
        helper.make_node("Add", ["a_leg", "m_sum"], ["a1"]),
        helper.make_node("Relu", ["a1"], ["h1"]),
        helper.make_node("MatMul", ["h1", "w2"], ["m2"]),
        helper.make_node("Add", ["b2", "m2"], ["torque" if not leg_bias else "plain"]),
    ]
    if leg_bias:
        nodes.append(helper.make_node("Add", ["plain", "per_leg"], ["torque"]))
    graph = helper.make_graph(
        nodes,
        "per_leg",
        [helper.make_tensor_value_info("x", TensorProto.FLOAT, [batch, LEGS, FEATURES])],
        [helper.make_tensor_value_info("torque", TensorProto.FLOAT, [batch, LEGS, OUT])],
        tensors,
    )
    return helper.make_model(graph, opset_imports=[helper.make_opsetid("", 17)])


def session(model: onnx.ModelProto, optimized: Path | None = None):
    options = onnxruntime.SessionOptions()
    if optimized is not None:
        options.optimized_model_filepath = str(optimized)
    return onnxruntime.InferenceSession(
        model.SerializeToString(), options, providers=["CPUExecutionProvider"]
    )


def test_a_per_leg_graph_runs_on_rows_in_fewer_fused_nodes(tmp_path):
    model = per_leg_network()
    x = np.random.default_rng(1).normal(size=(1, LEGS, FEATURES)).astype(np.float32)
    expected = session(model, tmp_path / "before.onnx").run(None, {"x": x})[0]
    assert rows_first(model)
    onnx.checker.check_model(model)
    ops = [node.op_type for node in model.graph.node]
    assert ops[0] == ops[-1] == "Reshape"  # rows in, the leading axis back out
    axes = [numpy_helper.to_array(t) for t in model.graph.initializer if t.name == "axes__rows"]
    assert [a.tolist() for a in axes] == [[0]]  # the sum over legs, on rows
    got = session(model, tmp_path / "after.onnx").run(None, {"x": x})[0]
    assert got.shape == (1, LEGS, OUT)
    np.testing.assert_allclose(got, expected, rtol=1e-5, atol=1e-5 * np.abs(expected).max())
    before, after = (
        [n.op_type for n in onnx.load(tmp_path / f"{name}.onnx").graph.node]
        for name in ("before", "after")
    )
    # every layer one node: its product, bias and ReLU fused (the leg's with the sum's)
    assert "Relu" in before and "Relu" not in after
    assert len(after) < len(before) - 2, (before, after)


@pytest.mark.parametrize(
    "model",
    [
        per_leg_network(batch=2),  # a batch of two: no axis of one to drop
        per_leg_network(sum_axis=0),  # a sum over the batch axis itself
        per_leg_network(leg_bias=True),  # a constant with the batch axis
    ],
    ids=["batch-2", "sum-over-batch", "constant-with-batch-axis"],
)
def test_a_graph_rows_would_change_is_left_as_it_was(model):
    before = model.SerializeToString()
    assert not rows_first(model)
    assert model.SerializeToString() == before

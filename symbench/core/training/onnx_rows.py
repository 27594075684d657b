"""A batch-1 ONNX graph computed on rows: the leading axis of size 1 dropped, so that ONNX
Runtime fuses each layer's MatMul, bias Add and ReLU into one Gemm node. Its fusions take
2-D operands only: on the exported (1, legs, features) tensors it runs three nodes per
layer, and each node costs about as much as the arithmetic of a batch-1 call.

sdnn on hexa, batch 1: 38 nodes after ONNX Runtime's optimizations -> 21 (see
`symbench bench models`, `infer_batch1_us_onnx`). The same function up to float32 rounding:
a layer fed two parts (sdnn's leg and the sum over legs) adds its bias to the sum's product
instead of the leg's, so that the leg's product, the sum's and the ReLU are one Gemm.

Only a graph whose inputs and outputs all have a leading axis of 1 and two axes after it,
and whose every node acts on rows alone (`ROW_WISE`, with 2-D weights, constants of no
more axes than the rows, reductions over other axes than the first), is rewritten: any
other graph (the graph networks' gathers, a dynamic batch) is left as it is.
"""

from __future__ import annotations

import numpy as np
import onnx
from onnx import helper, numpy_helper

from symbench.core.training.onnx_fold import GraphIndex

ELEMENTWISE = {"Add", "Sub", "Mul", "Div"}
ROW_WISE = ELEMENTWISE | {"MatMul", "Relu", "Identity", "LayerNormalization", "ReduceSum"}


def rows_first(model: onnx.ModelProto) -> bool:
    """Rewrite `model` in place when it qualifies (above); returns whether it did."""
    graph = GraphIndex(model)
    constants = _constant_values(graph)
    if not _qualifies(graph, constants):
        return False
    for node in [n for n in model.graph.node if n.op_type == "ReduceSum"]:
        axes = constants[node.input[1]]
        shifted = np.where(axes > 0, axes - 1, axes).astype(np.int64)
        node.input[1] = _add_constant(graph, f"{node.input[1]}__rows", shifted)
    for value in model.graph.input:
        _reshape_input(graph, value)
    for value in model.graph.output:
        _reshape_output(graph, value)
    _bias_on_second_part(graph)
    _sort(model.graph)
    del model.graph.value_info[:]  # shapes changed: ONNX Runtime infers them again
    used = {name for node in model.graph.node for name in node.input}
    unused = [n for n in model.graph.node if n.op_type == "Constant" and n.output[0] not in used]
    graph.remove(*unused)
    graph.drop_unused()
    return True


def _constant_values(graph: GraphIndex) -> dict[str, np.ndarray]:
    """Every constant tensor by name: the initializers and the Constant nodes' values."""
    values = dict(graph.constants)
    for node in graph.graph.node:
        if node.op_type == "Constant" and node.attribute and node.attribute[0].name == "value":
            values[node.output[0]] = numpy_helper.to_array(node.attribute[0].t)
    return values


def _leading_one(value: onnx.ValueInfoProto) -> bool:
    dims = value.type.tensor_type.shape.dim
    return len(dims) >= 3 and dims[0].HasField("dim_value") and dims[0].dim_value == 1


def _qualifies(graph: GraphIndex, constants: dict[str, np.ndarray]) -> bool:
    values = [*graph.graph.input, *graph.graph.output]
    if not all(_leading_one(v) for v in values):
        return False
    inputs = {v.name for v in graph.graph.input}
    if any(v.name in inputs for v in graph.graph.output):
        return False
    rows_rank = min(len(v.type.tensor_type.shape.dim) for v in graph.graph.input) - 1
    nodes = [node for node in graph.graph.node if node.op_type != "Constant"]
    return all(_row_wise(node, constants, rows_rank) for node in nodes)


def _row_wise(node: onnx.NodeProto, constants: dict[str, np.ndarray], rows_rank: int) -> bool:
    """Whether `node` computes the same on rows (of `rows_rank` axes) as on the batch of
    one row block."""
    attributes = {a.name: helper.get_attribute_value(a) for a in node.attribute}
    if node.op_type not in ROW_WISE:
        return False
    if node.op_type == "MatMul":
        weight = constants.get(node.input[1])
        return node.input[0] not in constants and weight is not None and weight.ndim == 2
    if node.op_type in ELEMENTWISE:  # a constant of more axes would broadcast the rows back
        return all(constants[name].ndim <= rows_rank for name in node.input if name in constants)
    if node.op_type == "LayerNormalization":
        return int(attributes.get("axis", -1)) < 0
    if node.op_type == "ReduceSum":
        axes = constants.get(node.input[1]) if len(node.input) > 1 else None
        keeps = attributes.get("keepdims", 1) == 1 and not attributes.get("noop_with_empty_axes")
        return keeps and axes is not None and axes.size > 0 and 0 not in axes
    return True  # Relu, Identity


def _add_constant(graph: GraphIndex, name: str, value: np.ndarray) -> str:
    graph.graph.initializer.append(numpy_helper.from_array(value, name))
    graph.constants[name] = value
    return name


def _dims(value: onnx.ValueInfoProto) -> np.ndarray:
    return np.array([d.dim_value for d in value.type.tensor_type.shape.dim], np.int64)


def _reshape_input(graph: GraphIndex, value: onnx.ValueInfoProto) -> None:
    """The input's rows (its leading axis dropped) in place of the input, for every node."""
    rows = f"{value.name}__rows"
    for node in graph.consumers(value.name):
        node.input[:] = [rows if name == value.name else name for name in node.input]
    shape = _add_constant(graph, f"{rows}__shape", _dims(value)[1:])
    graph.graph.node.insert(0, helper.make_node("Reshape", [value.name, shape], [rows]))


def _reshape_output(graph: GraphIndex, value: onnx.ValueInfoProto) -> None:
    """The output made as rows, then given its leading axis back."""
    rows = f"{value.name}__rows"
    producer = graph.producer[value.name]
    producer.output[:] = [rows if name == value.name else name for name in producer.output]
    shape = _add_constant(graph, f"{rows}__shape", _dims(value))
    graph.graph.node.append(helper.make_node("Reshape", [rows, shape], [value.name]))


def _bias_on_second_part(graph: GraphIndex) -> None:
    """`(x W1 + b) + s W2` -> `x W1 + (s W2 + b)` where the first sum feeds only the second:
    ONNX Runtime makes `s W2 + b` one Gemm, and `x W1 + (...)` with the ReLU after it
    another, where it left an Add and a ReLU standing."""
    producer = {name: node for node in graph.graph.node for name in node.output}
    for outer in [n for n in graph.graph.node if n.op_type == "Add"]:
        inner, second = (producer.get(name) for name in outer.input)
        if inner is None or second is None or inner.op_type != "Add":
            continue
        split = graph.split(inner)
        first = None if split is None else producer.get(split[0])
        if second.op_type != "MatMul" or first is None or first.op_type != "MatMul":
            continue
        if len(graph.consumers(inner.output[0])) != 1:
            continue
        bias = next(name for name in inner.input if name in graph.constants)
        inner.input[:] = [second.output[0], bias]
        outer.input[:] = [first.output[0], inner.output[0]]


def _sort(graph: onnx.GraphProto) -> None:
    """The nodes in an order where each comes after what it reads (ONNX requires it), the
    present order kept wherever it allows."""
    ready = {v.name for v in graph.input} | {t.name for t in graph.initializer} | {""}
    pending, order = list(graph.node), []
    while pending:
        node = next(n for n in pending if all(name in ready for name in n.input))
        pending.remove(node)
        order.append(node)
        ready.update(node.output)
    del graph.node[:]
    graph.node.extend(order)

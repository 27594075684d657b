"""Fold an exported model's input normalization and output de-normalization into the linear
layers next to them, so that ONNX Runtime runs four nodes fewer per call: the same function
up to float32 rounding, and about 1 us of sdnn's 25 us batch-1 call on hexa (measured side
by side; ONNX Runtime's own graph optimizations do not fold constants across a MatMul).

Input side, per graph input: `(x - mean) / std` feeding only `MatMul(., W) + b` becomes
`MatMul(x, W / std) + (b - (mean / std) W)`. Output side: `(MatMul(h, W) + b) * s + m` becomes
`MatMul(h, W s) + (b s + m)`. The statistics must be one value per feature of the last axis
(how `Normalizer` keeps them); a graph that does not have these shapes is left as it is.
"""

from __future__ import annotations

import numpy as np
import onnx
from onnx import numpy_helper


class GraphIndex:
    """The graph's nodes by what they produce and consume, and its constant tensors."""

    def __init__(self, model: onnx.ModelProto) -> None:
        self.graph = model.graph
        self.constants = {t.name: numpy_helper.to_array(t) for t in self.graph.initializer}
        self.producer = {name: node for node in self.graph.node for name in node.output}

    def consumers(self, name: str) -> list[onnx.NodeProto]:
        return [node for node in self.graph.node if name in node.input]

    def split(self, node: onnx.NodeProto) -> tuple[str, np.ndarray] | None:
        """A two-input node's variable input and its constant, or None if it has not one
        of each."""
        if len(node.input) != 2:
            return None
        variable = [name for name in node.input if name not in self.constants]
        constant = [name for name in node.input if name in self.constants]
        if len(variable) != 1 or len(constant) != 1:
            return None
        return variable[0], self.constants[constant[0]]

    def only_consumer(self, name: str, op: str) -> onnx.NodeProto | None:
        found = self.consumers(name)
        return found[0] if len(found) == 1 and found[0].op_type == op else None

    def replace_constant(self, node: onnx.NodeProto, value: np.ndarray) -> None:
        """Give `node` a new constant input in place of its old one (the old one stays
        for other nodes that use it, and is dropped by `drop_unused` when none does)."""
        old = next(name for name in node.input if name in self.constants)
        new = f"{old}__folded_{len(self.constants)}"
        self.graph.initializer.append(numpy_helper.from_array(value.astype(np.float32), new))
        self.constants[new] = value
        node.input[list(node.input).index(old)] = new

    def remove(self, *nodes: onnx.NodeProto) -> None:
        for node in nodes:
            self.graph.node.remove(node)

    def drop_unused(self) -> None:
        used = {name for node in self.graph.node for name in node.input}
        keep = [t for t in self.graph.initializer if t.name in used]
        del self.graph.initializer[:]
        self.graph.initializer.extend(keep)


def fold_normalization(model: onnx.ModelProto) -> int:
    """Fold in place what `model` allows; returns the number of normalizations folded."""
    graph = GraphIndex(model)
    folded = sum(_fold_input(graph, value.name) for value in model.graph.input)
    folded += sum(_fold_output(graph, value.name) for value in model.graph.output)
    graph.drop_unused()
    return folded


def _fold_input(graph: GraphIndex, name: str) -> bool:
    sub = graph.only_consumer(name, "Sub")
    div = None if sub is None else graph.only_consumer(sub.output[0], "Div")
    if sub is None or div is None or sub.input[0] != name or div.input[0] != sub.output[0]:
        return False
    mean, std = graph.split(sub), graph.split(div)
    if mean is None or std is None:
        return False
    layers = []
    for matmul in graph.consumers(div.output[0]):
        if matmul.op_type != "MatMul" or matmul.input[0] != div.output[0]:
            return False
        add = graph.only_consumer(matmul.output[0], "Add")
        weight = graph.constants.get(matmul.input[1])
        bias = None if add is None else graph.split(add)
        if weight is None or weight.ndim != 2 or add is None or bias is None:
            return False
        if not _per_feature(mean[1], std[1], weight.shape[0]):
            return False
        layers.append((matmul, weight, add, bias[1]))
    if not layers:
        return False
    for matmul, weight, add, old_bias in layers:
        graph.replace_constant(matmul, weight / std[1][:, None])
        graph.replace_constant(add, old_bias - (mean[1] / std[1]) @ weight)
        matmul.input[0] = name
    graph.remove(sub, div)
    return True


def _fold_output(graph: GraphIndex, name: str) -> bool:
    shift = graph.producer.get(name)
    scale = _producer_of_variable(graph, shift, "Add")
    add = _producer_of_variable(graph, scale, "Mul")
    matmul = _producer_of_variable(graph, add, "Add")
    if shift is None or scale is None or add is None or matmul is None:
        return False
    if matmul.op_type != "MatMul":
        return False
    weight = graph.constants.get(matmul.input[1])
    offset, factor, bias = graph.split(shift), graph.split(scale), graph.split(add)
    if weight is None or weight.ndim != 2:
        return False
    if offset is None or factor is None or bias is None:
        return False
    if not _per_feature(offset[1], factor[1], weight.shape[1]):
        return False
    if any(len(graph.consumers(node.output[0])) != 1 for node in (matmul, add, scale)):
        return False
    graph.replace_constant(matmul, weight * factor[1])
    graph.replace_constant(add, bias[1] * factor[1] + offset[1])
    add.output[0] = name
    graph.remove(scale, shift)
    return True


def _producer_of_variable(
    graph: GraphIndex, node: onnx.NodeProto | None, op: str
) -> onnx.NodeProto | None:
    """The node that makes `node`'s variable input, when `node` is an `op` of a variable and
    a constant."""
    if node is None or node.op_type != op:
        return None
    found = graph.split(node)
    return None if found is None else graph.producer.get(found[0])


def _per_feature(first: np.ndarray, second: np.ndarray, features: int) -> bool:
    """Whether two statistics hold one value per feature of a layer of `features`."""
    return first.shape == second.shape == (features,)

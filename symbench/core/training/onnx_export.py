"""A trained torch model as one ONNX file, its normalization included: what a controller
outside Python loads (ONNX Runtime from C++, say), and the fastest batch-1 call this
project has measured (`symbench bench models`: the closed loop calls a model at 1 kHz).

The file takes the model's raw inputs by their view keys (float32, any batch size) and
gives torques in N m, shape (batch, legs, 3); its metadata holds the model's description
(`TrainedModel.describe`) under the key `symbench`, so it names the data, configuration and
training it came from. `write_onnx` refuses to write a file whose outputs, run by ONNX
Runtime, differ from the model's own by more than float32 rounding.
"""

from __future__ import annotations

import json
import tempfile
import warnings
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np

from symbench.core.common.atomic import write_bytes_atomic
from symbench.core.common.errors import SymbenchError
from symbench.core.data.views.model_dims import ModelDims
from symbench.core.plugin.entries import ModelEntry
from symbench.core.training.normalization import Normalizer
from symbench.core.training.trained_model import TrainedModel

OPSET = 17
OUTPUT = "torque"
METADATA_KEY = "symbench"
PARITY_ROWS = 256
# |ONNX Runtime - torch| allowed, relative to the largest torque of the parity rows: a few
# float32 roundings through the network (both run float32, in different kernels)
PARITY_TOLERANCE = 1e-4


def onnx_bytes(
    entry: ModelEntry,
    dims: ModelDims,
    hyper: dict[str, Any],
    params: dict[str, np.ndarray],
    normalizer: Normalizer,
    metadata: dict[str, Any] | None = None,
    batch: int | None = None,
) -> bytes:
    """The network between its normalization and de-normalization as an ONNX model (float32;
    the normalizations folded into the layers next to them where `onnx_fold` can), `metadata`
    as JSON under `METADATA_KEY`. The batch size is `batch`, or any when None; fixed, it lets
    ONNX Runtime fold the shape arithmetic away (a batch-1 call of sdnn on hexa: 29 against
    41 us, measured side by side on a loaded 2-core machine)."""
    if entry.backend != "torch":
        raise SymbenchError(
            f"ONNX export takes a torch model; {entry.name} is a {entry.backend} model "
            f"(train it with --backend torch)"
        )
    import onnx
    import torch

    from symbench.core.training.backends.torch_backend import Normalized, build_network
    from symbench.core.training.onnx_fold import fold_normalization
    from symbench.core.training.onnx_rows import rows_first

    module = Normalized(build_network(entry, dims, hyper, params), normalizer, dims.keys)
    module = module.to(torch.float32).eval()
    rows = 2 if batch is None else batch
    example = tuple(torch.zeros((rows, *shape), dtype=torch.float32) for _, shape in dims.inputs)
    names = (*dims.keys, OUTPUT)
    with tempfile.TemporaryDirectory() as scratch, warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the legacy exporter's deprecation notice
        torch.onnx.export(
            module,
            example,
            Path(scratch) / "model.onnx",
            input_names=list(dims.keys),
            output_names=[OUTPUT],
            dynamic_axes=None if batch is not None else {name: {0: "batch"} for name in names},
            opset_version=OPSET,
            dynamo=False,
        )
        model = onnx.load(Path(scratch) / "model.onnx")
    fold_normalization(model)
    rows_first(model)  # a batch of 1: the layers on rows, one fused node each
    if metadata is not None:
        onnx.helper.set_model_props(model, {METADATA_KEY: json.dumps(metadata, sort_keys=True)})
    return model.SerializeToString()


def onnx_predictor(
    model: bytes, keys: tuple[str, ...], threads: int = 1
) -> Callable[[dict[str, np.ndarray]], np.ndarray]:
    """`predict(inputs)` running `model` in ONNX Runtime on `threads` threads: raw inputs by
    key in, torques in N m (float64) out. A model of fixed batch size is called through
    buffers bound once (its inputs are copied into them, ONNX Runtime writes the torques into
    one): about 2 us of a 27 us batch-1 call, measured side by side; so one such predictor
    must not be called from two threads at once."""
    import onnxruntime

    options = onnxruntime.SessionOptions()
    options.intra_op_num_threads = options.inter_op_num_threads = threads
    options.graph_optimization_level = onnxruntime.GraphOptimizationLevel.ORT_ENABLE_ALL
    session = onnxruntime.InferenceSession(model, options, providers=["CPUExecutionProvider"])
    shapes = {value.name: value.shape for value in session.get_inputs()}
    output = session.get_outputs()[0].shape
    if all(isinstance(d, int) for shape in (*shapes.values(), output) for d in shape):
        return _bound_predictor(session, keys, shapes, output)

    def predict(inputs: dict[str, np.ndarray]) -> np.ndarray:
        feed = {k: np.asarray(inputs[k], np.float32) for k in keys}
        return session.run([OUTPUT], feed)[0].astype(np.float64)

    return predict


def _bound_predictor(
    session: Any, keys: tuple[str, ...], shapes: dict[str, list[int]], output: list[int]
) -> Callable[[dict[str, np.ndarray]], np.ndarray]:
    """`onnx_predictor` of a model whose every shape is fixed."""
    buffers = {k: np.empty(shapes[k], np.float32) for k in keys}
    torques = np.empty(output, np.float32)
    binding = session.io_binding()
    for key, buffer in buffers.items():
        binding.bind_cpu_input(key, buffer)
    binding.bind_output(OUTPUT, "cpu", 0, np.float32, torques.shape, torques.ctypes.data)

    def predict(inputs: dict[str, np.ndarray]) -> np.ndarray:
        for key, buffer in buffers.items():
            given = inputs[key]
            if given.shape != buffer.shape:
                raise SymbenchError(
                    f"this ONNX model takes {key} of shape {buffer.shape} (a fixed batch of "
                    f"{buffer.shape[0]} rows); got shape {given.shape}"
                )
            buffer[...] = given  # float32 from any float (a plain copy: 0.1 us, copyto 0.3)
        session.run_with_iobinding(binding)
        return torques.astype(np.float64)

    return predict


def parity_inputs(model: TrainedModel, rows: int = PARITY_ROWS) -> dict[str, np.ndarray]:
    """Inputs spread as the model's training inputs were: its normalizer's mean plus its std
    times standard normal draws (seeded), in every input's shape."""
    rng = np.random.default_rng(0)
    inputs = {}
    for key, shape in model.dims.inputs:
        mean, std = model.normalizer.stats[key]
        inputs[key] = (mean + std * rng.standard_normal((rows, *shape))).astype(np.float32)
    return inputs


def write_onnx(model: TrainedModel, path: Path, batch: int | None = None) -> tuple[float, int]:
    """`model` as an ONNX file at `path` (written atomically; of batch size `batch`, any when
    None), after checking ONNX Runtime against the model on `parity_inputs` (in calls of
    `batch` rows); returns the largest difference (N m) and the rows compared."""
    data = onnx_bytes(
        model.entry,
        model.dims,
        model.hyper,
        model.params,
        model.normalizer,
        model.describe(),
        batch,
    )
    call = PARITY_ROWS if batch is None else batch
    inputs = parity_inputs(model, -(-PARITY_ROWS // call) * call)
    expected = model.predict(inputs)
    predict = onnx_predictor(data, model.dims.keys)
    got = np.concatenate(
        [
            predict({k: v[start : start + call] for k, v in inputs.items()})
            for start in range(0, len(expected), call)
        ]
    )
    difference = float(np.max(np.abs(got - expected)))
    scale = float(np.max(np.abs(expected)))
    if not difference <= PARITY_TOLERANCE * max(scale, 1e-12):
        raise SymbenchError(
            f"the ONNX export of {model.entry.name} differs from the model by {difference:.3g} "
            f"N m (largest torque {scale:.3g}): not written"
        )
    write_bytes_atomic(Path(path), data)
    return difference, len(expected)

"""PyTorch backend: `entry.build(dims, **hyper)` returns a `torch.nn.Module` whose
`forward(**inputs)` maps normalized view inputs to normalized torques (N, n_legs, 3).

Uncompiled predictions run the network as a frozen TorchScript trace: for batch-1 control-loop
calls the per-operator overhead of eager mode dominates, and the trace computes the same
float32 operations bitwise (sdnn on hexa: 148 -> 68 us; torch.compile: 100-120 us).

Predictions and validation run the network on at most PREDICT_ROWS rows at a time: an
evaluator's call of a whole test set at once (gnn on hexa: tensors of edges x rows x 64, a
few hundred MB) leaves every element-wise operation waiting on memory, while 256-row pieces
stay in cache: 2.5k -> 8.5k predictions/s for gnn on hexa, sdnn 10k -> 31k, sdgnn 15k ->
54k, ffnn 76k -> 180k (one core, AMD EPYC). Each row's float32 operations are the same
whatever the size of the call it is in, so predictions are unchanged bit for bit (tested).

Torch runs one intra-op thread unless SYMBENCH_TORCH_THREADS says otherwise: the benchmark's
matrices (batch 64, latent 128) are too small to gain from threads, and on a 2-core machine
shared with the simulator or other runs, two threads fighting for cores made training up to
6 times slower (measured side by side: 3,951 vs 668 samples/s for sdnn on a loaded machine).
"""

from __future__ import annotations

import os
import warnings
from collections.abc import Callable
from typing import Any

import numpy as np
import torch
import torch.nn.functional as F

from symbench.core.common.errors import SymbenchError
from symbench.core.data.views.model_dims import ModelDims
from symbench.core.plugin.entries import ModelEntry
from symbench.core.training.backends.checks import build_error, check_output, check_params
from symbench.core.training.backends.torch_adam import FusedAdam
from symbench.core.training.normalization import TARGET_KEY, Normalizer


def _torch_threads() -> int:
    """SYMBENCH_TORCH_THREADS, checked: a positive whole number (default 1)."""
    value = os.environ.get("SYMBENCH_TORCH_THREADS", "1")
    if not value.strip().isdigit() or int(value) < 1:
        raise SymbenchError(
            f"SYMBENCH_TORCH_THREADS must be a positive whole number, not {value!r}"
        )
    return int(value)


torch.set_num_threads(_torch_threads())

Params = dict[str, np.ndarray]
EVAL_CHUNK = 8192  # rows per float64 partial sum of the validation loss
PREDICT_ROWS = 256  # rows per forward call of predictions and validation (see top)
_DTYPES = {np.dtype(np.float32): torch.float32, np.dtype(np.float64): torch.float64}


def in_pieces(
    entry: ModelEntry, dims: ModelDims, run: Callable[..., torch.Tensor], xs: list[torch.Tensor]
) -> torch.Tensor:
    """`run(*xs)`, called on at most PREDICT_ROWS rows at a time (see the module's top), each
    piece's output shape checked before the pieces are joined."""
    pieces = []
    for start in range(0, max(len(xs[0]), 1), PREDICT_ROWS):
        rows = [x[start : start + PREDICT_ROWS] for x in xs]
        pieces.append(run(*rows))
        check_output(entry, dims, pieces[-1].shape, len(rows[0]))
    return pieces[0] if len(pieces) == 1 else _joined(pieces, len(xs[0]))


def _joined(pieces: list[torch.Tensor], rows: int) -> torch.Tensor:
    """The pieces as one tensor laid out in memory as one call's output would be: a graph
    network's output is a transposed view (edges outermost), and a sum over a tensor runs in
    its memory order, so `torch.cat`'s row-major copy changed the validation loss's last bit
    (gnn, thousands of rows)."""
    first = pieces[0]
    outermost_first = sorted(range(first.dim()), key=first.stride, reverse=True)
    shape = (rows, *first.shape[1:])
    out = torch.empty([shape[d] for d in outermost_first], dtype=first.dtype)
    out = out.permute(*np.argsort(outermost_first).tolist())
    start = 0
    for piece in pieces:
        out[start : start + len(piece)] = piece
        start += len(piece)
    return out


def build_network(
    entry: ModelEntry, dims: ModelDims, hyper: dict[str, Any], params: Params | None = None
) -> torch.nn.Module:
    """The entry's network, with `params` loaded when given."""
    try:
        net = entry.build(dims, **hyper)
    except Exception as exc:
        raise build_error(entry, exc) from exc
    if not isinstance(net, torch.nn.Module):
        raise build_error(
            entry, TypeError(f"build returned {type(net).__name__}, expected a torch.nn.Module")
        )
    if params is not None:
        load_params(entry, net, params)
    return net


def load_params(entry: ModelEntry, net: torch.nn.Module, params: Params) -> None:
    expected = {k: tuple(v.shape) for k, v in net.state_dict().items()}
    check_params(entry, expected, params)
    net.load_state_dict(
        {k: torch.from_numpy(np.array(v, dtype=np.float32)) for k, v in params.items()}
    )


def to_numpy(module: torch.nn.Module) -> Params:
    return {k: v.detach().cpu().numpy().copy() for k, v in module.state_dict().items()}


class Normalized(torch.nn.Module):
    """The network between input normalization and target de-normalization."""

    def __init__(self, net: torch.nn.Module, normalizer: Normalizer, keys: tuple[str, ...]):
        super().__init__()
        self.net, self.keys = net, keys
        for key in (*keys, TARGET_KEY):
            mean, std = normalizer.stats[key]
            self.register_buffer(f"{key}_mean", torch.from_numpy(np.asarray(mean, np.float64)))
            self.register_buffer(f"{key}_std", torch.from_numpy(np.asarray(std, np.float64)))

    def forward(self, *xs: torch.Tensor) -> torch.Tensor:
        inputs = {
            k: (x - getattr(self, f"{k}_mean")) / getattr(self, f"{k}_std")
            for k, x in zip(self.keys, xs)
        }
        return self.net(**inputs) * self.target_std + self.target_mean


class ByPosition(torch.nn.Module):
    """`net` called with its inputs in `keys` order, as tracing passes them."""

    def __init__(self, net: Callable[..., torch.Tensor], keys: tuple[str, ...]):
        super().__init__()
        self.net, self.keys = net, keys

    def forward(self, *xs: torch.Tensor) -> torch.Tensor:
        return self.net(**dict(zip(self.keys, xs)))


def traced(
    module: torch.nn.Module, dims: ModelDims, dtype: torch.dtype, freeze: bool = True
) -> torch.nn.Module:
    """`module` as a TorchScript trace (frozen for inference), checked against eager mode at
    two batch sizes; `module` itself when it cannot be traced faithfully (data-dependent
    control flow). Unfrozen, the trace shares the module's parameters and trains them."""
    gen = torch.Generator().manual_seed(0)

    def example(n: int) -> tuple[torch.Tensor, ...]:
        return tuple(
            torch.randn((n, *shape), generator=gen, dtype=dtype) for _, shape in dims.inputs
        )

    try:
        with warnings.catch_warnings(), torch.no_grad():
            # torch.jit is deprecated in favour of torch.compile, which is slower here (see top)
            warnings.simplefilter("ignore")
            trace = torch.jit.trace(module, example(1), check_inputs=[example(3), example(1)])
            return torch.jit.freeze(trace) if freeze else trace
    except Exception:
        return module


class TorchTrainer:
    def __init__(
        self,
        entry: ModelEntry,
        dims: ModelDims,
        net: torch.nn.Module,
        learning_rate: float,
        compiled: bool,
    ):
        self.entry, self.dims, self.net = entry, dims, net
        self.opt = FusedAdam(list(net.parameters()))
        self.learning_rate = learning_rate
        self.forward = torch.compile(net) if compiled else net
        # uncompiled training runs a trace: the same operations, bitwise, with less Python
        # per step (gnn +11 %, sdnn +3 % samples/s)
        self.val_forward = ByPosition(self.forward, dims.keys)
        by_position = ByPosition(self.forward, dims.keys).train()
        self.train_forward = (
            by_position if compiled else traced(by_position, dims, torch.float32, freeze=False)
        )

    def set_data(self, train_inputs, train_target, val_inputs, val_target) -> None:
        def tensors(d):
            return {k: torch.from_numpy(np.asarray(v, np.float32)) for k, v in d.items()}

        self.train_inputs, self.val_inputs = tensors(train_inputs), tensors(val_inputs)
        self.train_target = torch.from_numpy(np.asarray(train_target, np.float32))
        self.val_target = torch.from_numpy(np.asarray(val_target, np.float32))

    def train_epoch(self, order: np.ndarray, rate_scale: np.ndarray | None = None) -> float:
        self.net.train()
        total = torch.zeros(())
        scales = np.ones(len(order)) if rate_scale is None else rate_scale
        for idx, scale in zip(torch.from_numpy(order), scales, strict=True):
            # index_select: the same rows as v[idx], without advanced indexing's overhead
            batch = {k: v.index_select(0, idx) for k, v in self.train_inputs.items()}
            out = self.train_forward(*(batch[k] for k in self.dims.keys))
            # before the loss, which would broadcast (N, legs, 1) against (N, legs, 3) silently
            check_output(self.entry, self.dims, out.shape, len(idx))
            loss = F.mse_loss(out, self.train_target.index_select(0, idx))
            self.opt.zero_grad()
            loss.backward()
            self.opt.step(self.learning_rate * float(scale))
            total += loss.detach()
        return float(total) / len(order)

    @torch.no_grad()
    def val_loss(self) -> float:
        self.net.eval()
        n = len(self.val_target)
        sse = 0.0
        for start in range(0, n, EVAL_CHUNK):
            batch = [self.val_inputs[k][start : start + EVAL_CHUNK] for k in self.dims.keys]
            out = in_pieces(self.entry, self.dims, self.val_forward, batch)
            err = out - self.val_target[start : start + EVAL_CHUNK]
            sse += float((err.double() ** 2).sum())
        return sse / self.val_target.numel()

    def params(self) -> Params:
        return to_numpy(self.net)

    def load_params(self, params: Params) -> None:
        load_params(self.entry, self.net, params)

    def optimizer_state(self) -> Params:
        return {
            f"{i}/{k}": v.detach().numpy().copy()
            for i, st in self.opt.state_dict().items()
            for k, v in st.items()
        }

    def load_optimizer_state(self, state: Params) -> None:
        per_param: dict[int, dict[str, torch.Tensor]] = {}
        for key, value in state.items():
            i, name = key.split("/")
            per_param.setdefault(int(i), {})[name] = torch.from_numpy(value.copy())
        self.opt.load_state_dict(per_param)


class TorchBackend:
    name = "torch"
    default_compiled = False  # torch.compile costs tens of seconds on CPU; see `bench models`

    def init_params(self, entry, dims, hyper, seed) -> Params:
        with torch.random.fork_rng(devices=[]):
            torch.manual_seed(seed)
            return to_numpy(build_network(entry, dims, hyper))

    def parameter_shapes(self, entry, dims, hyper) -> dict[str, tuple[int, ...]]:
        try:
            with torch.device("meta"):  # shapes only: nothing is allocated or initialised
                net = build_network(entry, dims, hyper)
        except SymbenchError:  # a build that reads tensor values (e2cnn's bases) needs data
            net = build_network(entry, dims, hyper)
        return {k: tuple(v.shape) for k, v in net.state_dict().items()}

    def make_predictor(
        self, entry, dims, hyper, params, normalizer, dtype=np.float32, compiled=False
    ):
        np_dtype = np.dtype(dtype)
        module = Normalized(build_network(entry, dims, hyper, params), normalizer, dims.keys)
        module = module.to(_DTYPES[np_dtype]).eval()
        run = torch.compile(module) if compiled else traced(module, dims, _DTYPES[np_dtype])
        keys = dims.keys

        def predict(inputs: dict[str, np.ndarray]) -> np.ndarray:
            with torch.inference_mode():
                xs = [torch.from_numpy(np.asarray(inputs[k], np_dtype)) for k in keys]
                y = in_pieces(entry, dims, run, xs)
            return y.numpy().astype(np.float64)

        return predict

    def make_trainer(self, entry, dims, hyper, params, learning_rate, compiled=False):
        return TorchTrainer(
            entry, dims, build_network(entry, dims, hyper, params), learning_rate, compiled
        )


BACKEND = TorchBackend()

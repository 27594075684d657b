"""Whatever bytes a checkpoint holds, damaged or crafted with a valid content hash, loading it
gives a one-line error naming the file or exactly the model that was saved."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from strategies import JSON, edited

from symbench.core.common.errors import SymbenchError
from symbench.core.data.views.model_dims import dims_for
from symbench.core.plugin import registry
from symbench.core.training.backends import get_backend
from symbench.core.training.checkpoints import read_tensors, write_tensors
from symbench.core.training.normalization import Normalizer
from symbench.core.training.trained_model import TENSORS, TrainedModel


@pytest.fixture(scope="module")
def saved(tmp_path_factory):
    """A small SDNN saved as `symbench run` saves its best model: (its file, the model)."""
    entry = registry.model("sdnn", "torch")
    dims = dims_for("leg_grouped", "acc", 4)
    hyper = {"latent": 8}
    params = get_backend("torch").init_params(entry, dims, hyper, seed=0)
    model = TrainedModel(
        entry,
        dims,
        hyper,
        Normalizer.random(dims, np.random.default_rng(0)),
        params,
        {"train_loss": [1.0], "val_loss": [0.5]},
        0,
        {"seed": 0},
        "done",
    )
    folder = tmp_path_factory.mktemp("model")
    model.save(folder)
    return folder / TENSORS, model


@st.composite
def damaged(draw: st.DrawFn, content: bytes) -> bytes:
    """`content` with bytes changed, cut off, inserted or appended."""
    data = bytearray(content)
    for _ in range(draw(st.integers(1, 3))):
        at = draw(st.integers(0, len(data)))
        kind = draw(st.sampled_from(["change", "cut", "insert"]))
        if kind == "change" and at < len(data):
            data[at] = draw(st.integers(0, 255))
        elif kind == "cut":
            del data[at:]
        else:
            data[at:at] = draw(st.binary(min_size=1, max_size=8))
    return bytes(data)


def load_or_refusal(folder):
    """The model in `folder`, or None after checking the refusal names the file in one line."""
    try:
        return TrainedModel.load(folder)
    except SymbenchError as error:
        assert str(folder) in str(error) and "\n" not in str(error), str(error)
        return None


def assert_same(loaded: TrainedModel, model: TrainedModel) -> None:
    assert loaded.describe() == model.describe()
    assert loaded.params.keys() == model.params.keys()
    for key, value in model.params.items():
        np.testing.assert_array_equal(loaded.params[key], value)
    for key, (mean, std) in model.normalizer.stats.items():
        np.testing.assert_array_equal(loaded.normalizer.stats[key][0], mean)
        np.testing.assert_array_equal(loaded.normalizer.stats[key][1], std)


@given(data=st.data())
def test_a_damaged_checkpoint_is_refused_or_loads_as_saved(tmp_path_factory, saved, data):
    path, model = saved
    folder = tmp_path_factory.mktemp("damaged")
    (folder / TENSORS).write_bytes(data.draw(damaged(path.read_bytes())))
    loaded = load_or_refusal(folder)
    if loaded is not None:  # only bytes that mean nothing changed (JSON whitespace, say)
        assert_same(loaded, model)


@given(data=st.data())
def test_a_crafted_checkpoint_is_refused_or_loads_as_what_it_says(tmp_path_factory, saved, data):
    arrays, description = read_tensors(saved[0])
    crafted = data.draw(
        edited(
            {"arrays": {k: v.shape for k, v in arrays.items()}, "description": description}
        ).filter(lambda d: isinstance(d, dict))
        | JSON.map(lambda d: {"description": d})
    )
    shapes = crafted.get("arrays", {}) if isinstance(crafted.get("arrays"), dict) else {}
    tensors = {k: np.zeros(s) for k, s in shapes.items() if _is_shape(s)}
    folder = tmp_path_factory.mktemp("crafted")
    write_tensors(folder / TENSORS, tensors, crafted.get("description"))  # hashed: looks genuine
    loaded = load_or_refusal(folder)
    if loaded is not None:
        assert loaded.describe()["hyper"] == crafted["description"]["hyper"]
        params = {k.removeprefix("params/") for k in tensors if k.startswith("params/")}
        assert loaded.params.keys() == params


def _is_shape(value) -> bool:
    return (
        isinstance(value, (list, tuple))
        and len(value) <= 3
        and all(isinstance(n, int) and not isinstance(n, bool) and 0 <= n <= 64 for n in value)
    )

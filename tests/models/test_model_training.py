"""The training protocols: every model learns, stops by its protocol's rule, resumes exactly."""

from __future__ import annotations

import numpy as np
import pytest
from model_sizes import BACKENDS, MODELS, SMALL

from symbench.core.common.errors import SymbenchError
from symbench.core.config.protocols import Converge, Cosine, Paper, rate_scale, schedule_class
from symbench.core.plugin import registry
from symbench.core.training.loop import TrainConfig, batch_order, train
from symbench.core.training.trained_model import TrainedModel


def converge(
    checks: int, every: int, patience: int = 10, protocol: str = "converge", **kwargs
) -> TrainConfig:
    """The converge (or cosine) protocol with a budget of `checks` validation checks `every`
    steps apart (patience 10 unless given: the budget ends these short trainings)."""
    steps = Cosine if protocol == "cosine" else Converge
    schedule = steps(max_steps=checks * every, eval_every=every, patience=patience)
    return TrainConfig(schedule=schedule, **{"progress": False, **kwargs})


# JAX's graph networks compile for half a minute on 2 cores: -m slow
LEARNING = [
    pytest.param(n, b, marks=pytest.mark.slow)
    if (b, n) in {("jax", "gnn"), ("jax", "sdgnn")}
    else (n, b)
    for n in MODELS
    for b in BACKENDS
]


@pytest.mark.parametrize(("name", "backend"), LEARNING)
def test_validation_loss_falls(name, backend, smoke):
    entry = registry.model(name, backend)
    tr, va = smoke
    model = train(entry, tr[entry.view], va[entry.view], converge(6, 16, hyper=SMALL[name]))
    val = model.history["val_loss"]
    assert len(val) == 6 and min(val[1:]) < 0.8 * val[0], val
    assert model.steps == 96 and model.stopped_by == "budget"
    assert model.best_epoch == int(np.argmin(val))
    y = model.predict(va[entry.view].inputs)
    assert y.shape == (256, 4, 3) and y.dtype == np.float64
    # predictions are in N m: their error matches the normalized validation loss
    target_std = model.normalizer.stats["target"][1]
    err = ((y - va[entry.view].target) / target_std) ** 2
    assert np.isclose(err.mean(), val[model.best_epoch], rtol=1e-3)


def _interrupted_after(monkeypatch, steps: int) -> None:
    """The next training stops, as by Ctrl-C, when it reaches `steps` gradient steps."""
    from symbench.core.training import loop

    def scale(protocol, span, max_steps):
        if span.start >= steps:
            monkeypatch.undo()
            raise KeyboardInterrupt
        return rate_scale(protocol, span, max_steps)

    monkeypatch.setattr(loop, "rate_scale", scale)


# every protocol in torch by default; in JAX (a minute each on 2 cores) under -m slow
@pytest.mark.parametrize(
    ("protocol", "backend"),
    [
        *((p, "torch") for p in ("converge", "cosine", "paper")),
        *(pytest.param(p, "jax", marks=pytest.mark.slow) for p in ("converge", "cosine", "paper")),
    ],
)
def test_interrupted_training_resumes_exactly(backend, protocol, smoke, tmp_path, monkeypatch):
    """Under converge and cosine the checks fall every 3 steps of 4-batch epochs: a check,
    and so a resume, in the middle of an epoch continues its batch order (and, under cosine,
    its learning-rate curve)."""
    entry = registry.model("sdnn", backend)
    tr, va = (s["leg_grouped"].take(np.arange(256)) for s in smoke)
    if protocol != "paper":
        config, shorter = (converge(n, 3, hyper=SMALL["sdnn"], protocol=protocol) for n in (4, 2))
    else:
        config, shorter = (
            TrainConfig(schedule=Paper(max_epochs=n), hyper=SMALL["sdnn"], progress=False)
            for n in (4, 2)
        )
    whole = train(entry, tr, va, config)
    if protocol == "cosine":  # its rate depends on the budget: stopped mid-way instead
        _interrupted_after(monkeypatch, 6)
        with pytest.raises(KeyboardInterrupt):
            train(entry, tr, va, config, tmp_path)
    else:  # a finished shorter training continues under the larger budget
        first = train(entry, tr, va, shorter, tmp_path)
        assert len(first.history["val_loss"]) == 2
    resumed = train(entry, tr, va, config, tmp_path)
    assert resumed.steps == whole.steps == (12 if protocol != "paper" else 16)
    # torch repeats itself bit for bit; XLA's CPU kernels may round the last bit differently
    # for buffers that were reloaded, so allow float32 rounding
    assert resumed.best_epoch == whole.best_epoch
    for key in ("train_loss", "val_loss"):
        np.testing.assert_allclose(resumed.history[key], whole.history[key], rtol=1e-6)
    for k, v in whole.params.items():
        np.testing.assert_allclose(resumed.params[k], v, rtol=1e-5, atol=1e-7)


def test_resume_refuses_a_checkpoint_of_another_configuration(smoke, tmp_path):
    entry = registry.model("sdnn", "torch")
    tr, va = (s["leg_grouped"].take(np.arange(128)) for s in smoke)
    train(entry, tr, va, converge(1, 2, hyper=SMALL["sdnn"]), tmp_path)
    with pytest.raises(SymbenchError, match="another model, data or configuration"):
        train(entry, tr, va, converge(1, 2, seed=1, hyper=SMALL["sdnn"]), tmp_path)


def test_resume_refuses_a_checkpoint_of_other_data_of_the_same_size(smoke, tmp_path):
    entry = registry.model("sdnn", "torch")
    config = converge(1, 2, hyper=SMALL["sdnn"])
    tr, va = (s["leg_grouped"].take(np.arange(128)) for s in smoke)
    train(entry, tr, va, config, tmp_path)
    other = tr.take(np.arange(128)[::-1])  # same samples, another order: other data
    with pytest.raises(SymbenchError, match="another model, data or configuration"):
        train(entry, other, va, config, tmp_path)


@pytest.mark.parametrize(
    "ratio, patience, epochs, stopped_by",
    [(1e9, 3, 3, "overfitting-rule"), (0.0, 3, 5, "epoch-cap")],
)
def test_the_paper_stopping_rule(ratio, patience, epochs, stopped_by, smoke):
    """ratio x val > train every epoch: stop after `patience` epochs; never: run to the cap."""
    entry = registry.model("sdnn", "torch")
    tr, va = (s["leg_grouped"].take(np.arange(128)) for s in smoke)
    model = train(
        entry,
        tr,
        va,
        TrainConfig(
            schedule=Paper(max_epochs=5, stop_ratio=ratio, stop_patience=patience),
            hyper=SMALL["sdnn"],
            progress=False,
        ),
    )
    assert len(model.history["val_loss"]) == epochs and model.stopped_by == stopped_by
    assert model.steps == 2 * epochs  # two batches of 64 per epoch


def test_converge_stops_once_validation_stops_improving(smoke):
    """A learning rate too small to move any weight: the validation loss never improves on
    the first check, so training stops `patience` checks later, long before the budget, and
    keeps the first check's parameters."""
    entry = registry.model("sdnn", "torch")
    tr, va = (s["leg_grouped"].take(np.arange(128)) for s in smoke)
    model = train(entry, tr, va, converge(50, 2, patience=3, learning_rate=1e-30))
    assert len(model.history["val_loss"]) == 4 and model.steps == 8
    assert model.stopped_by == "patience" and model.best_epoch == 0 and model.best_step == 2


def test_converge_gives_every_training_fraction_the_same_budget(smoke):
    """Half the data, the same number of gradient steps (the paper protocol's epochs would
    give it half as many)."""
    entry = registry.model("ffnn", "torch")
    tr, va = (s["vector"] for s in smoke)
    config = converge(3, 20, hyper=SMALL["ffnn"])
    full, half = (train(entry, tr.take(np.arange(n)), va, config) for n in (1024, 512))
    assert full.steps == half.steps == 60
    assert full.stopped_by == half.stopped_by == "budget"


def test_val_stride_checks_every_nth_validation_row_and_leaves_older_configs_alone(smoke):
    """Stride 2 selects on exactly the rows a stride-1 training given every second row sees;
    at stride 1 the config (kept in checkpoints) is what it was before the option existed."""
    entry = registry.model("ffnn", "torch")
    tr, va = (s["vector"] for s in smoke)
    thinned = train(entry, tr, va, converge(2, 16, hyper=SMALL["ffnn"], val_stride=2))
    given = train(
        entry, tr, va.take(np.arange(0, len(va), 2)), converge(2, 16, hyper=SMALL["ffnn"])
    )
    full = train(entry, tr, va, converge(2, 16, hyper=SMALL["ffnn"]))
    assert thinned.history["val_loss"] == given.history["val_loss"]
    assert thinned.history["val_loss"] != full.history["val_loss"]
    assert thinned.history["train_loss"] == full.history["train_loss"]
    assert "val_stride" not in full.config and thinned.config["val_stride"] == 2
    with pytest.raises(SymbenchError, match="val_stride must be at least 1"):
        TrainConfig(val_stride=0)


def test_an_unknown_protocol_is_refused():
    with pytest.raises(SymbenchError, match="unknown training protocol 'fast'"):
        schedule_class("fast")


def test_a_protocol_setting_given_flat_names_the_typed_form():
    with pytest.raises(SymbenchError, match=r"not TrainConfig\(max_epochs=\.\.\.\) but .*Paper"):
        TrainConfig(max_epochs=3)
    with pytest.raises(SymbenchError, match="other protocol family"):
        TrainConfig(schedule=Converge(), unused=Cosine())


def test_the_flat_layout_lists_both_families_in_the_order_records_keep():
    config = TrainConfig(schedule=Paper(max_epochs=7), unused=Converge(30, 10, 2), val_stride=2)
    flat = config.to_dict()
    assert list(flat) == [
        "seed", "batch_size", "protocol", "max_steps", "eval_every", "patience", "val_stride",
        "max_epochs", "stop_ratio", "stop_patience", "learning_rate", "hyper", "compile",
    ]  # fmt: skip
    assert (flat["protocol"], flat["max_steps"], flat["max_epochs"]) == ("paper", 30, 7)
    assert TrainConfig.from_dict(flat) == config


def test_batch_order_is_a_seeded_permutation_per_epoch():
    a, b = batch_order(200, 64, 0, 0), batch_order(200, 64, 0, 1)
    assert a.shape == (3, 64) and len(set(a.ravel())) == 192
    assert not np.array_equal(a, b) and np.array_equal(a, batch_order(200, 64, 0, 0))


def test_best_checkpoint_round_trips_without_pickle(smoke, tmp_path):
    entry = registry.model("sdgnn", "torch")
    tr, va = smoke
    model = train(
        entry,
        tr["leg_grouped"],
        va["leg_grouped"],
        converge(2, 8, hyper=SMALL["sdgnn"]),
        tmp_path,
    )
    loaded = TrainedModel.load(tmp_path / "best")
    assert (loaded.steps, loaded.stopped_by) == (model.steps, model.stopped_by) == (16, "budget")
    assert loaded.n_params == model.n_params and loaded.history == model.history
    np.testing.assert_array_equal(
        loaded.predict(va["leg_grouped"].inputs), model.predict(va["leg_grouped"].inputs)
    )
    raw = (tmp_path / "best" / "model.safetensors").read_bytes()
    assert b"normalization/x/mean" in raw[:4096] and not raw.startswith(
        b"\x80"
    )  # no pickle protocol


def test_corrupt_or_foreign_checkpoints_are_named(tmp_path):
    (tmp_path / "model.safetensors").write_bytes(b"not a checkpoint")
    with pytest.raises(SymbenchError, match="not a readable safetensors file"):
        TrainedModel.load(tmp_path)


def test_bad_data_is_named(smoke):
    entry = registry.model("sdnn", "torch")
    tr, va = smoke
    with pytest.raises(SymbenchError, match="consumes the leg_grouped/acc view"):
        train(
            entry,
            tr["vector"],
            va["vector"],
            TrainConfig(schedule=Paper(max_epochs=1), progress=False),
        )
    bad = tr["leg_grouped"].take(np.arange(64))
    bad.inputs["x"][0, 0, 0] = np.nan
    with pytest.raises(SymbenchError, match="NaN"):
        train(
            entry, bad, va["leg_grouped"], TrainConfig(schedule=Paper(max_epochs=1), progress=False)
        )


def test_cosine_decays_the_rate_from_the_models_to_zero_over_the_budget():
    np.testing.assert_array_equal(rate_scale("converge", range(0, 500), 1000), np.ones(500))
    np.testing.assert_array_equal(rate_scale("paper", range(7, 9), 10), np.ones(2))
    scale = rate_scale("cosine", range(0, 1000), 1000)
    assert scale[0] == 1.0 and np.isclose(scale[500], 0.5) and 0 < scale[-1] < 1e-4
    assert np.all(np.diff(scale) < 0)
    # a round in the middle of the budget is that part of the same curve
    np.testing.assert_array_equal(rate_scale("cosine", range(300, 400), 1000), scale[300:400])


def test_cosine_trains_differently_and_refuses_to_resume_under_another_budget(smoke, tmp_path):
    entry = registry.model("sdnn", "torch")
    tr, va = (s["leg_grouped"].take(np.arange(256)) for s in smoke)
    cosine = train(entry, tr, va, converge(2, 3, hyper=SMALL["sdnn"], protocol="cosine"), tmp_path)
    constant = train(entry, tr, va, converge(2, 3, hyper=SMALL["sdnn"]))
    assert cosine.history["train_loss"][0] != constant.history["train_loss"][0]
    longer = converge(4, 3, hyper=SMALL["sdnn"], protocol="cosine")
    with pytest.raises(SymbenchError, match="another model, data or configuration"):
        train(entry, tr, va, longer, tmp_path)

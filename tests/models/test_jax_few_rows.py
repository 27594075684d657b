"""A JAX model called with few rows (a control loop's batch 1) multiplies row-major
(`layers.FEW_ROWS`), a training batch feature-major: both forms must compute the same
function, or the equivariance the kit checks on batches would not hold at batch 1."""

from __future__ import annotations

import numpy as np
import pytest

from symbench.core.data.views.model_dims import dims_of
from symbench.core.plugin import registry
from symbench.core.robot.specs import load_robot
from symbench.core.training.backends import get_backend
from symbench.core.training.normalization import Normalizer
from symbench.testing.synthetic import synthetic_views

TOLERANCE = {np.float64: 1e-12, np.float32: 1e-5}
SLOW = pytest.mark.slow


def _cases():
    """Dense and the graph network on hexa by default: sdnn, and sdgnn in float32 (what a
    control loop calls). XLA compiles each graph network for 20 s to a minute on 2 cores, so
    sdgnn in float64, gnn, and the other robots run under -m slow."""
    for model in ("sdnn", "sdgnn", "gnn"):
        for robot in ("hexa", "magneto", "nona"):
            for dtype in (np.float64, np.float32):
                control_loops = model == "sdnn" or (model, dtype) == ("sdgnn", np.float32)
                fast = robot == "hexa" and control_loops
                yield pytest.param(model, robot, dtype, marks=[] if fast else [SLOW])


@pytest.mark.parametrize(("model", "robot", "dtype"), list(_cases()))
def test_one_row_at_a_time_predicts_what_the_batch_predicts(model, robot, dtype):
    entry = registry.model(model, "jax")
    data = synthetic_views(load_robot(robot).n_legs, 64, seed=1)[entry.view]
    backend = get_backend("jax")
    dims = dims_of(data)
    params = backend.init_params(entry, dims, {}, 0)
    predict = backend.make_predictor(entry, dims, {}, params, Normalizer.fit(data), dtype, True)
    batch = predict(data.inputs)
    # rounding only: float32 to 1e-5 of the output's scale, float64 to 1e-12
    atol = TOLERANCE[dtype] * float(np.abs(batch).max())
    for i in range(0, 64, 9):
        one = predict({k: v[i : i + 1] for k, v in data.inputs.items()})
        np.testing.assert_allclose(one[0], batch[i], rtol=TOLERANCE[dtype], atol=atol)

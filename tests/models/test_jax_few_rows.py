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


@pytest.mark.parametrize("dtype", [np.float64, np.float32])
# hexa by default; XLA compiles each robot's graph networks for a minute on 2 cores (-m slow)
@pytest.mark.parametrize(
    "robot", ["hexa", *(pytest.param(r, marks=SLOW) for r in ("magneto", "nona"))]
)
# Dense and the graph network (sdgnn's; gnn's, which XLA compiles for a minute, -m slow)
@pytest.mark.parametrize("model", ["sdnn", "sdgnn", pytest.param("gnn", marks=SLOW)])
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

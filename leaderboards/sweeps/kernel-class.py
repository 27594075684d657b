"""Prints this machine's torch training kernel class (what records name in
`hardware.training_kernels`, as a sweep's one-thread worker runs) as a folder name: trainings
reproduce bit for bit only within one class, so a training carried between machines
(leaderboards/pending/trainings/<class>/) is reused only on a machine of its class.

    python leaderboards/sweeps/kernel-class.py
"""

import re

import symbench.core.training.backends.torch_backend  # noqa: F401  (sets the thread count)
from symbench.core.training.kernels import training_kernels

print(re.sub(r"[^a-z0-9]+", "-", training_kernels("torch").lower()).strip("-"))

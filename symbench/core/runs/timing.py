"""What a run spent, as its record's `timings_s` says: wall seconds per stage and per
evaluator, and the CPU seconds of the whole run.

Wall seconds alone overstate a run's cost whenever other work shares its core or it waits
for another run's training (the v7 board's records of hexa's seed 0 sum to 3.76 hours for
runs that took 1.94 CPU-hours on 2026-12-07, docs/concepts.md, Presets) and understate it
when a run trains ahead in worker processes; CPU seconds (user and system, of the run's
process and of the worker processes it started and waited for) are the core-seconds it
used, whatever shared the machine.
"""

from __future__ import annotations

import resource
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any, TypeVar

T = TypeVar("T")

RETRAINING_KEY = "retraining_s"  # the trainings a run's evaluators asked for
STAGES = ("dataset_s", "training_s", RETRAINING_KEY, "evaluation_s")  # wall seconds, in order
CPU_KEY = "cpu_s"  # the whole run's CPU seconds, worker processes included
_EVALUATOR = ("evaluation_s[", "]")  # an evaluator's key: its name between these


def evaluator_key(name: str) -> str:
    """The `timings_s` key of one evaluator's own wall seconds (a part of `evaluation_s`)."""
    return f"{_EVALUATOR[0]}{name}{_EVALUATOR[1]}"


def evaluator_of(key: str) -> str:
    """The evaluator a `timings_s` key times (`evaluator_key`), or "" for any other key."""
    start, end = _EVALUATOR
    if key.startswith(start) and key.endswith(end) and len(key) > len(start) + len(end):
        return key[len(start) : -len(end)]
    return ""


def cpu_seconds() -> float:
    """CPU seconds (user and system) used so far by this process and by the worker processes
    it has started and waited for."""
    own = resource.getrusage(resource.RUSAGE_SELF)
    workers = resource.getrusage(resource.RUSAGE_CHILDREN)
    return own.ru_utime + own.ru_stime + workers.ru_utime + workers.ru_stime


@dataclass
class Timer:
    """Seconds per stage of a run, summed over the calls measured under one name."""

    timings: dict[str, float] = field(default_factory=dict)

    def measure(
        self, name: str, fn: Callable[..., T], *args: Any, less: str = "", **kwargs: Any
    ) -> T:
        """`fn(*args, **kwargs)`, its wall seconds added under `name`, less those measured
        meanwhile under `less` when given: an evaluator's own time, without the trainings
        it asked for (counted under `retraining_s`)."""
        before = self.timings.get(less, 0.0)
        start = time.perf_counter()
        try:
            return fn(*args, **kwargs)
        finally:
            inside = self.timings.get(less, 0.0) - before if less else 0.0
            self.add(name, time.perf_counter() - start - inside)

    def add(self, name: str, seconds: float) -> None:
        self.timings[name] = self.timings.get(name, 0.0) + seconds

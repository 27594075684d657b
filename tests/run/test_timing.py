"""A run's timings: an evaluator's own seconds leave out the trainings it asked for, and CPU
seconds count the worker processes a run waited for."""

from __future__ import annotations

import multiprocessing
import time

from symbench.core.runs import timing
from symbench.core.runs.timing import Timer, cpu_seconds, evaluator_key, evaluator_of

BURN_S = 0.3


def _burn() -> None:
    """Busy for BURN_S seconds of this process's own CPU time."""
    while time.process_time() < BURN_S:
        pass


class _Clock:
    """A perf_counter that moves only when `sleep` is called: the test's seconds are exact."""

    def __init__(self) -> None:
        self.now = 0.0

    def perf_counter(self) -> float:
        return self.now

    def sleep(self, seconds: float) -> None:
        self.now += seconds


def test_an_evaluator_is_timed_without_the_trainings_inside_it(monkeypatch):
    clock = _Clock()
    monkeypatch.setattr(timing, "time", clock)
    timer = Timer()

    def evaluate() -> str:
        timer.measure("retraining_s", clock.sleep, 2.0)
        clock.sleep(0.5)
        return "metrics"

    name = evaluator_key("generalization")
    assert timer.measure(name, evaluate, less="retraining_s") == "metrics"
    assert timer.timings == {"retraining_s": 2.0, name: 0.5}
    timer.measure("training_s", clock.sleep, 0.25)  # without `less`, every second counts
    timer.measure(name, clock.sleep, 0.25, less="retraining_s")  # summed over calls
    assert timer.timings == {"retraining_s": 2.0, name: 0.75, "training_s": 0.25}


def test_evaluator_keys_name_their_evaluator_and_nothing_else():
    for name in ("closed-loop", "torque-error", "my[odd]name"):
        assert evaluator_of(evaluator_key(name)) == name
    for key in ("evaluation_s", "retraining_s", "cpu_s", "evaluation_s[]"):
        assert evaluator_of(key) == ""


def test_cpu_seconds_count_a_worker_process_once_it_is_waited_for():
    before = cpu_seconds()
    worker = multiprocessing.get_context("spawn").Process(target=_burn)
    worker.start()
    worker.join()
    assert worker.exitcode == 0
    # the parent only waited: nearly all of the difference is the worker's
    assert cpu_seconds() - before >= BURN_S

"""A run's timings: an evaluator's own seconds leave out the trainings it asked for, and CPU
seconds count the worker processes a run waited for."""

from __future__ import annotations

import multiprocessing
import time

from symbench.core.runs.timing import Timer, cpu_seconds, evaluator_key, evaluator_of

BURN_S = 0.3


def _burn() -> None:
    """Busy for BURN_S seconds of this process's own CPU time."""
    while time.process_time() < BURN_S:
        pass


def test_an_evaluator_is_timed_without_the_trainings_inside_it():
    timer = Timer()

    def evaluate() -> str:
        timer.measure("retraining_s", time.sleep, 0.2)
        time.sleep(0.05)
        return "metrics"

    assert timer.measure(evaluator_key("generalization"), evaluate, less="retraining_s") == (
        "metrics"
    )
    own = timer.timings["evaluation_s[generalization]"]
    assert 0.04 < own < 0.15 and timer.timings["retraining_s"] >= 0.2
    timer.measure("training_s", time.sleep, 0.05)  # without `less`, every second counts
    assert timer.timings["training_s"] >= 0.05


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

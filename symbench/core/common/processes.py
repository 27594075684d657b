"""Worker processes that never outlive the command that started them.

Workers are spawned (torch, JAX and MuJoCo hold threads, which fork would copy half-alive)
and each one watches its parent: when the parent dies, even by SIGKILL, which runs no
clean-up, the worker exits instead of idling (or computing) forever. Ctrl-C cancels the work
not yet started and waits for the work under way, whose results land on disk (everything is
written atomically), so a caller that counts finished work on disk afterwards counts it all.
"""

from __future__ import annotations

import contextlib
import multiprocessing
import os
import threading
from collections.abc import Callable, Iterable
from concurrent.futures import FIRST_COMPLETED, Future, ProcessPoolExecutor, wait
from multiprocessing.connection import wait as wait_for_ready
from typing import Any


def exit_with_parent() -> None:
    """Pool initializer: a daemon thread ends this worker once its parent has died (the
    parent's sentinel, a pipe only the parent holds open, becomes ready)."""
    parent = multiprocessing.parent_process()
    if parent is None:
        return

    def watch() -> None:
        wait_for_ready([parent.sentinel])
        os._exit(1)

    threading.Thread(target=watch, name="symbench-exit-with-parent", daemon=True).start()


def run_each(
    fn: Callable[[Any], Any],
    items: Iterable[Any],
    workers: int,
    on_done: Callable[[Any], None],
    environment: Callable[[], contextlib.AbstractContextManager] = contextlib.nullcontext,
) -> None:
    """`fn(item)` for every item in `workers` spawned processes, calling `on_done` with each
    result as it comes; the processes start inside `environment()` (their environment
    variables, say). An exception (Ctrl-C included) cancels what has not started."""
    pool = ProcessPoolExecutor(
        workers, mp_context=multiprocessing.get_context("spawn"), initializer=exit_with_parent
    )
    try:
        with environment():  # the workers start at the first submit
            pending: set[Future] = {pool.submit(fn, item) for item in items}
        while pending:
            done, pending = wait(pending, return_when=FIRST_COMPLETED)
            for future in done:
                on_done(future.result())
    finally:
        pool.shutdown(wait=True, cancel_futures=True)

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
from concurrent.futures.process import BrokenProcessPool
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


class WorkerDied(Exception):
    """Raised by `run_each` once every other item has run: `items` are those whose worker
    process died (killed by the system for memory, say) even when each ran alone."""

    def __init__(self, items: list[Any]) -> None:
        super().__init__(f"{len(items)} item(s) lost with their worker process")
        self.items = items


def run_each(
    fn: Callable[[Any], Any],
    items: Iterable[Any],
    workers: int,
    on_done: Callable[[Any], None],
    environment: Callable[[], contextlib.AbstractContextManager] = contextlib.nullcontext,
    one_each: bool = False,
) -> None:
    """`fn(item)` for every item in `workers` spawned processes, calling `on_done` with each
    result as it comes; the processes start inside `environment()` (their environment
    variables, say), and with `one_each` a process ends after one item, so that what an item
    leaves in memory never adds up over items (heavy items: runs, trainings). An exception
    (Ctrl-C included) cancels what has not started.

    A worker that dies takes its pool with it, and every item then under way: those are run
    again afterwards, one at a time in a pool of their own (two heavy items at once are the
    usual cause), and the others go on in a fresh pool meanwhile; the items that die even
    alone are raised as `WorkerDied`, after everything else has run."""
    lost = _run_in_pools(fn, list(items), workers, on_done, environment, one_each)
    if lost:
        lost = _run_in_pools(fn, lost, 1, on_done, environment, one_each)
    if lost:
        raise WorkerDied(lost)


def _run_in_pools(
    fn: Callable[[Any], Any],
    items: list[Any],
    workers: int,
    on_done: Callable[[Any], None],
    environment: Callable[[], contextlib.AbstractContextManager],
    one_each: bool,
) -> list[Any]:
    """Runs `items`, at most `workers` under way at once, so that the items under way when a
    worker dies are known; returns them (the rest ran in a fresh pool)."""
    queue, lost = list(reversed(items)), list[Any]()
    while queue:
        pool = ProcessPoolExecutor(
            workers,
            mp_context=multiprocessing.get_context("spawn"),
            initializer=exit_with_parent,
            max_tasks_per_child=1 if one_each else None,
        )
        try:
            under_way: dict[Future, Any] = {}
            while queue or under_way:
                while queue and len(under_way) < workers:
                    item = queue.pop()
                    with environment():  # a worker starts at the submit that needs it
                        under_way[pool.submit(fn, item)] = item
                done, _ = wait(under_way, return_when=FIRST_COMPLETED)
                broken = [f for f in done if isinstance(f.exception(), BrokenProcessPool)]
                for future in done.difference(broken):
                    on_done(future.result())
                    del under_way[future]
                if broken:
                    lost += under_way.values()
                    break
        finally:
            pool.shutdown(wait=True, cancel_futures=True)
    return lost

"""Thread settings of `symbench bench models`: how many cores one measurement gets.

A thread count is only honest as a count of cores: a process confined to n cores (its CPU
affinity) and telling torch to use n threads computes with n cores, however many threads its
libraries start. XLA keeps the pool size symbench pins for training (`kernels.XLA_POOL`), so
a setting measures the very step training compiles, on its n cores. Both libraries start
their pools once, when they load, so a process is confined before it imports either.
"""

from __future__ import annotations

import os
import sys
from pathlib import Path
from typing import Any

import click

ALL = "all"
XLA_POOL_THREAD = "XLAEigen"  # in the name of each thread of XLA's CPU compute pool


def available_cores() -> list[int]:
    """The cores this process may run on: its affinity, which taskset or a container's
    cpuset can make smaller than the machine."""
    return sorted(os.sched_getaffinity(0))


class ThreadCounts(click.ParamType):
    """Comma-separated thread counts, each a number of cores or `all` (every available one):
    sorted, and one setting where two name the same count (`1,all` on a single core)."""

    name = "threads"

    def convert(
        self, value: Any, param: click.Parameter | None, ctx: click.Context | None
    ) -> list[int]:
        if isinstance(value, list):
            return value
        items = [item.strip() for item in str(value).split(",") if item.strip()]
        if not items:
            self.fail(f"{value!r} names nothing (a comma-separated list is expected)", param, ctx)
        cores = len(available_cores())
        return sorted({self._count(item, cores, param, ctx) for item in items})

    def _count(
        self, item: str, cores: int, param: click.Parameter | None, ctx: click.Context | None
    ) -> int:
        if item == ALL:
            return cores
        try:
            count = int(item)
        except ValueError:
            self.fail(f"{item!r} is neither a number of threads nor {ALL!r}", param, ctx)
        if count < 1:
            self.fail(f"{count} threads: a setting needs at least 1", param, ctx)
        if count > cores:
            self.fail(f"{count} threads: this process may use only {cores} cores", param, ctx)
        return count


def confine(count: int) -> list[int]:
    """Run this process and every thread it starts from now on on its first `count` cores,
    torch with `count` intra-op threads (read by the torch backend when it loads) and XLA with
    its pinned pool; the cores."""
    loaded = sorted({"torch", "jax"} & set(sys.modules))
    if loaded:
        raise RuntimeError(f"{' and '.join(loaded)} loaded before the thread setting was made")
    cores = available_cores()[:count]
    os.sched_setaffinity(0, cores)
    os.environ["SYMBENCH_TORCH_THREADS"] = str(count)
    return cores


def threads_named(part: str) -> int:
    """How many of this process's threads have `part` in their name (Linux's /proc)."""
    tasks = Path("/proc/self/task").iterdir()
    return sum(part in (task / "comm").read_text() for task in tasks)

"""`symbench sweep --executor ray`: runs as Ray tasks, on a cluster or a local one.

Ray retries an address that nothing answers for minutes, silently; so a cluster address is
first tried here with a plain TCP connection and a timeout, and a wrong one is an error
naming it within seconds.
"""

from __future__ import annotations

import os
import socket
from collections.abc import Callable
from typing import Any

from symbench.core.common.errors import SymbenchError

CONNECT_TIMEOUT_S = 10.0
AUTOMATIC = (None, "auto", "local")  # addresses Ray resolves itself, without a network wait


def host_and_port(address: str) -> tuple[str, int]:
    """`HOST:PORT` or `ray://HOST:PORT` (IPv6 hosts in brackets) as (host, port)."""
    host, _, port = address.removeprefix("ray://").rpartition(":")
    if not host or not port.isdigit() or not 0 < int(port) < 65536:
        raise SymbenchError(
            f"--address {address!r}: expected HOST:PORT (or ray://HOST:PORT, auto, local)"
        )
    return host.strip("[]"), int(port)


def check_reachable(address: str, timeout: float = CONNECT_TIMEOUT_S) -> None:
    """An error naming `address` unless something accepts a TCP connection there in time."""
    try:
        socket.create_connection(host_and_port(address), timeout=timeout).close()
    except OSError as exc:
        reason = "timed out" if isinstance(exc, TimeoutError) else exc.strerror or str(exc)
        raise SymbenchError(
            f"cannot reach the Ray cluster at {address} ({reason}, "
            f"{timeout:g} s timeout); check --address"
        ) from None


def connect(address: str | None) -> Any:
    """The `ray` module, initialised against `address` (None: a new local cluster)."""
    try:
        import ray
    except ImportError:
        raise SymbenchError(
            "--executor ray needs Ray: pip install -c constraints.txt 'symbench[ray]'"
        ) from None
    if address not in AUTOMATIC:
        check_reachable(address)
    # workers see the same cache and headless rendering as this process
    env = {k: os.environ[k] for k in ("SYMBENCH_HOME", "MUJOCO_GL") if k in os.environ}
    try:
        ray.init(
            address=address,
            ignore_reinit_error=True,
            log_to_driver=False,
            include_dashboard=False,
            runtime_env={"env_vars": env},
        )
    except (ConnectionError, ValueError) as exc:
        raise SymbenchError(
            f"cannot connect to the Ray cluster at {address}: {' '.join(str(exc).split())}"
        ) from None
    return ray


def run_all(
    ray: Any, fn: Callable[[Any], str], items: list[Any], report: Callable[[str], None]
) -> list[str]:
    """`fn(item)` for every item as a Ray task (one CPU each) of the cluster `ray` is
    connected to; the keys `fn` returns, in the order they finish."""
    remote = ray.remote(num_cpus=1)(fn)
    pending = {remote.remote(item): item for item in items}
    done = []
    while pending:
        ready, _ = ray.wait(list(pending), num_returns=1)
        for ref in ready:
            done.append(ray.get(ref))
            pending.pop(ref)
            report(f"finished {done[-1]}")
    return done

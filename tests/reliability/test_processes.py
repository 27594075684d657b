"""Worker processes end with their command, Ctrl-C is counted right, a wrong Ray address is
an error in seconds, `--workers` means one thing, and what symbench writes others can read."""

from __future__ import annotations

import contextlib
import os
import re
import signal
import socket
import subprocess
import sys
import time
from collections.abc import Iterator
from pathlib import Path

import psutil
import pytest
from cli_invoke import error_line, invoke
from synthetic_raw import write_logs

from symbench.core.common.processes import WorkerDied, run_each
from symbench.core.data.importing.importer import import_logs
from symbench.core.runs import sweep as sweeping
from symbench.core.runs.cli import run as run_command
from symbench.core.runs.cli import verify as verify_cli
from symbench.core.runs.results import read_record, write_record

SYMBENCH = str(Path(sys.executable).parent / "symbench")


def sweep_command(output: Path, *extra: str, seeds: str = "0,1") -> list[str]:
    """Quick runs on the stand-in smoke dataset (four with the default seeds), two at a time."""
    return [
        SYMBENCH,
        "sweep",
        "--models",
        "sdnn,ffnn",
        "--robots",
        "hexa",
        "--seeds",
        seeds,
        "--preset",
        "smoke",
        "--evaluators",
        "torque-error",
        "--workers",
        "2",
        "--output",
        str(output),
        *extra,
    ]


def _default_sigint() -> None:
    signal.signal(signal.SIGINT, signal.SIG_DFL)


@contextlib.contextmanager
def running(command: list[str], home: Path) -> Iterator[subprocess.Popen]:
    """`command` in a session of its own, whatever is left of which is killed at the end.
    A Ctrl-C reaches it as a terminal's would: SIGINT at its default even when the tests run
    where it is ignored (a shell's background job inherits SIGINT ignored, and Python then
    never raises KeyboardInterrupt)."""
    proc = subprocess.Popen(
        command,
        env={**os.environ, "SYMBENCH_HOME": str(home)},
        stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT,
        text=True,
        start_new_session=True,
        preexec_fn=_default_sigint,
    )
    try:
        yield proc
    finally:
        with contextlib.suppress(ProcessLookupError):
            os.killpg(proc.pid, signal.SIGKILL)


def workers_of(proc: subprocess.Popen, n: int, timeout: float = 120) -> list[psutil.Process]:
    """The `n` pool workers `proc` spawned (multiprocessing's resource tracker left out)."""
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        assert proc.poll() is None, proc.stdout.read()
        workers = [
            p
            for p in psutil.Process(proc.pid).children()
            if "resource_tracker" not in " ".join(p.cmdline())
        ]
        if len(workers) >= n:
            return workers
        time.sleep(0.1)
    raise AssertionError(f"no {n} workers within {timeout} s")


def test_sweep_workers_exit_when_the_sweep_is_killed(smoke_hexa, home, tmp_path):
    with running(sweep_command(tmp_path / "results"), home) as proc:
        workers = workers_of(proc, 2)
        os.kill(proc.pid, signal.SIGKILL)  # no clean-up can run, as after the OOM killer
        proc.wait()
        _, alive = psutil.wait_procs(workers, timeout=30)
        assert [p for p in alive if p.status() != psutil.STATUS_ZOMBIE] == []


@pytest.mark.slow  # a sweep of real runs
def test_ctrl_c_summary_counts_every_finished_run(smoke_hexa, home, tmp_path):
    """Twelve runs, so that on a loaded machine the sweep is still busy when both workers
    are up and Ctrl-C arrives (with four, a slow second worker let them all finish first)."""
    with running(sweep_command(tmp_path / "results", seeds="0,1,2,3,4,5"), home) as proc:
        workers_of(proc, 2)
        os.kill(proc.pid, signal.SIGINT)  # the runs under way finish while the sweep stops
        output = proc.communicate(timeout=300)[0]
    assert proc.returncode == 1, output
    found = re.search(
        r"interrupted with (\d+) of 12 runs finished; run the same command again", output
    )
    assert found, output
    records = list((tmp_path / "results").glob("*.json"))
    assert all(read_record(r) for r in records)
    assert int(found.group(1)) == len(records) < 12


@pytest.mark.slow  # a sweep of real runs
def test_a_sweep_goes_on_when_a_worker_is_killed_and_reruns_its_runs(smoke_hexa, home, tmp_path):
    """The out-of-memory killer's SIGKILL of one worker costs a rerun, not the sweep."""
    with running(sweep_command(tmp_path / "results"), home) as proc:
        os.kill(workers_of(proc, 2)[0].pid, signal.SIGKILL)
        output = proc.communicate(timeout=600)[0]
    assert proc.returncode == 0, output
    records = sorted((tmp_path / "results").glob("*.json"))
    assert len(records) == 4 and all(read_record(r) for r in records), output


def _tries(folder: Path, i: int) -> int:
    """Counts this try of item `i` and returns how many came before it."""
    before = len(list(folder.glob(f"tried-{i}-*")))
    (folder / f"tried-{i}-{before}").touch()
    return before


def _square_unless_doomed(item: tuple[Path, int]) -> int:
    """Dies like a killed process on item 3, always; item 1 waits until item 3 has started,
    and on its first try it then outlasts the pool that item 3 breaks."""
    folder, i = item
    before = _tries(folder, i)
    if i == 3:
        os._exit(9)
    if i == 1:
        deadline = time.monotonic() + 60
        while not list(folder.glob("tried-3-*")) and time.monotonic() < deadline:
            time.sleep(0.01)
        if before == 0:
            time.sleep(2)  # the pool breaks meanwhile (its result, if any, is then lost)
    return i * i


def test_run_each_reruns_lost_items_alone_and_names_those_that_die_alone(tmp_path):
    """Items 1 and 3 are under way together in the pool of two; item 3's death takes item 1
    with it, which then completes when run alone, while item 3 dies alone too and is named.
    (Whether item 1 had started before the pool broke is the scheduler's say: either way it
    must complete, and item 3 must have been tried exactly twice.)"""
    results: list[int] = []
    items = [(tmp_path, i) for i in (1, 3, 0, 2, 4, 5)]
    with pytest.raises(WorkerDied) as died:
        run_each(_square_unless_doomed, items, 2, results.append)
    assert [i for _, i in died.value.items] == [3]
    assert sorted(results) == [0, 1, 4, 16, 25]
    assert len(list(tmp_path.glob("tried-3-*"))) == 2


def _pid(_: int) -> int:
    return os.getpid()


def test_one_each_gives_every_item_a_process_of_its_own():
    """What a run leaves in memory (12 GB in a worker that made many) cannot add up; without
    `one_each` the two workers take every item (which of them, the scheduler says)."""
    for one_each, processes in ((True, {4}), (False, {1, 2})):
        pids: list[int] = []
        run_each(_pid, range(4), 2, pids.append, one_each=one_each)
        assert len(pids) == 4 and len(set(pids)) in processes


def test_a_ray_address_where_no_cluster_answers_is_an_error_within_seconds(
    smoke_hexa, home, tmp_path
):
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]  # free: nothing listens there
    command = sweep_command(
        tmp_path / "results", "--executor", "ray", "--address", f"127.0.0.1:{port}"
    )
    with running(command, home) as proc:
        output = proc.communicate(timeout=60)[0]
    assert proc.returncode == 1
    assert f"Error: cannot reach the Ray cluster at 127.0.0.1:{port} (Connection refused" in output


@pytest.mark.parametrize(
    "args",
    [
        ("run", "--model", "sdnn", "--robot", "hexa"),
        ("sweep", "--models", "sdnn", "--robots", "hexa"),
        ("data", "generate", "--robot", "hexa"),
        ("verify", __file__),
    ],
    ids=["run", "sweep", "data generate", "verify"],
)
def test_workers_0_is_refused_alike_by_every_command(monkeypatch, args):
    def never(*args, **kwargs):
        raise AssertionError("the command started working")

    for module, name in (
        (run_command, "run_spec"),
        (sweeping, "sweep"),
        (verify_cli, "verify_record"),
    ):
        monkeypatch.setattr(module, name, never)
    message = error_line(invoke(*args, "--workers", "0"), 2)
    assert "Invalid value for '--workers': 0 is not in the range x>=1" in message


def test_records_and_datasets_are_readable_by_others(home, tmp_path, make_record):
    previous = os.umask(0o022)
    try:
        write_record(make_record(), tmp_path / "r.json")
        dataset = import_logs(write_logs(tmp_path / "logs"), "logs")
    finally:
        os.umask(previous)
    files = [tmp_path / "r.json", *dataset.root.rglob("*.*")]
    assert {oct(f.stat().st_mode & 0o777) for f in files} == {"0o644"}

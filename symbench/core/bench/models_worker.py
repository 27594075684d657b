"""One thread setting of `symbench bench models`, measured in a process of its own.

Torch sizes its thread pool once, when it loads, and XLA starts its pool's threads on the
cores the process has then, so one process cannot measure two settings: the command runs
`python -m symbench.core.bench.models_worker JOB OUT` per setting, which confines itself to
its cores before importing either (see `threads`),
measures (see `model_rates`) and writes the setting's figures to OUT as JSON. Its progress
and anything it prints come back line by line through one pipe, so nothing it prints can
mix into the command's own output.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import tempfile
from collections.abc import Callable
from pathlib import Path
from typing import Any

import symbench
from symbench.core.bench.threads import confine
from symbench.core.common.errors import SymbenchError

MODULE = "symbench.core.bench.models_worker"


def measure_in_child(job: dict[str, Any], relay: Callable[[str], None]) -> dict[str, Any]:
    """The figures of `job` (its "threads" the setting), taken by a child process; `relay`
    gets each line the child prints."""
    # the child imports the symbench this process runs, wherever that is installed
    root = str(Path(symbench.__file__).resolve().parents[1])
    path = [root, *filter(None, os.environ.get("PYTHONPATH", "").split(os.pathsep))]
    env = {**os.environ, "PYTHONPATH": os.pathsep.join(path)}
    with tempfile.TemporaryDirectory() as folder:
        out = Path(folder) / "setting.json"
        command = [sys.executable, "-m", MODULE, json.dumps(job), str(out)]
        with subprocess.Popen(
            command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=env
        ) as child:
            assert child.stdout is not None
            for line in child.stdout:
                relay(line.rstrip("\n"))
        if child.returncode != 0:
            raise SymbenchError(
                f"the {job['threads']}-thread measurement failed (exit status "
                f"{child.returncode}; its output is above)"
            )
        result: dict[str, Any] = json.loads(out.read_text())
        return result


def main(job_json: str, out: str) -> None:
    job = json.loads(job_json)
    cores = confine(job["threads"])
    from symbench.core.bench.model_rates import measure_setting

    def say(line: str) -> None:
        print(line, flush=True)

    Path(out).write_text(json.dumps(measure_setting(job, cores, say)))


if __name__ == "__main__":
    main(*sys.argv[1:])

"""Standard output for commands: a reader that went away (`symbench ... | head`) ends the
command quietly with status 141, like any program writing into a closed pipe; rich's own
console would exit 1, the status of a failure."""

from __future__ import annotations

import os
import sys
from typing import NoReturn

from rich.console import Console

CLOSED_PIPE_STATUS = 141


def closed_stdout() -> NoReturn:
    """Stop quietly after the reader of standard output went away: what is still buffered
    goes to /dev/null (so flushing at exit cannot raise again), exit status 141."""
    devnull = os.open(os.devnull, os.O_WRONLY)
    os.dup2(devnull, sys.stdout.fileno())
    sys.exit(CLOSED_PIPE_STATUS)


class StdoutConsole(Console):
    """A rich console on standard output that stops like `closed_stdout` on a closed pipe."""

    def on_broken_pipe(self) -> None:
        closed_stdout()

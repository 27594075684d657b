"""`symbench` run in this process as its console script runs it, and the checks every bad
input must pass: an exit status, a one-line message, never a traceback."""

from __future__ import annotations

import traceback

from click.testing import CliRunner, Result

from symbench.core.cli import build_cli


def invoke(*args: str) -> Result:
    """The result of `symbench ARGS`; fails the test when an exception escaped."""
    result = CliRunner().invoke(build_cli(), [str(a) for a in args])
    if result.exception is not None and not isinstance(result.exception, SystemExit):
        raise AssertionError(
            "an exception escaped the command line:\n"
            + "".join(traceback.format_exception(result.exception))
        )
    return result


def error_line(result: Result, status: int) -> str:
    """The one error line of a command that ended with `status` (1 failure, 2 usage error)."""
    assert result.exit_code == status, (result.exit_code, result.output)
    assert "Traceback" not in result.output
    errors = [line for line in result.stderr.splitlines() if line.startswith("Error")]
    assert len(errors) == 1, result.stderr
    return " ".join(result.stderr[result.stderr.index(errors[0]) :].split())


def refusal(result: Result) -> str:
    """The one error line of a command that refused its input (1 failure, 2 usage error);
    never an "internal error", the command line's word for an exception nobody expected."""
    line = error_line(result, result.exit_code if result.exit_code in (1, 2) else 1)
    assert not line.startswith("Error: internal error"), line
    return line

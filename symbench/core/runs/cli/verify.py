"""`symbench verify`: re-run records from scratch and compare every metric."""

from __future__ import annotations

import json
import tempfile
from pathlib import Path

import click
from rich.table import Table

from symbench.core.common.cli_types import NON_NEGATIVE, WORKERS
from symbench.core.common.console import StdoutConsole
from symbench.core.common.errors import SymbenchError, first_of
from symbench.core.runs.results import read_record
from symbench.core.runs.verify import (
    ATOL,
    RTOL,
    Tolerance,
    Verification,
    kernel_class_warning,
    verify_record,
)

SHOWN = 10  # names in the summary line; the table above it lists every value


def _table(result: Verification) -> Table:
    table = Table(title=f"{result.path} ({result.key}), {result.seconds:.0f} s")
    for column in ("metric", "recorded", "reproduced", "agree"):
        table.add_column(column, overflow="fold")
    for c in result.checks:
        agree = "not recorded" if not c.recorded_here else "yes" if c.agree else "[red]NO[/]"
        table.add_row(
            c.name, "-" if not c.recorded_here else repr(c.recorded), repr(c.reproduced), agree
        )
    return table


@click.command("verify")
@click.argument("records", nargs=-1, required=True, type=click.Path(path_type=Path, exists=True))
@click.option(
    "--rtol",
    default=RTOL,
    show_default=True,
    type=NON_NEGATIVE,
    help="Relative tolerance (deterministic CPU training reproduces bit for bit).",
)
@click.option(
    "--atol", default=ATOL, show_default=True, type=NON_NEGATIVE, help="Absolute tolerance."
)
@click.option(
    "--workers",
    default=2,
    show_default=True,
    type=WORKERS,
    help="Worker processes at once, simulating a missing dataset.",
)
@click.option("--json", "as_json", is_flag=True, help="Print JSON instead of tables.")
def verify(
    records: tuple[Path, ...], rtol: float, atol: float, workers: int, as_json: bool
) -> None:
    """Re-run each RECORD (its dataset, seed, hyper-parameters and evaluators) and compare
    every metric; exits with 1 when any disagrees."""
    tolerance = Tolerance(rtol, atol)
    import symbench.core.training.backends.torch_backend  # noqa: F401  (sets its thread count)
    from symbench.core.training.kernels import training_kernel_problems

    for problem in training_kernel_problems():  # then bit-for-bit agreement is not expected
        click.echo(
            f"warning: {problem}; training may not reproduce records made elsewhere", err=True
        )
    for path in records:
        try:
            warning = kernel_class_warning(read_record(path))
        except SymbenchError:
            continue  # verify_record names the problem
        if warning:
            click.echo(f"warning: {warning}", err=True)
    with tempfile.TemporaryDirectory(prefix="symbench-verify-") as workdir:
        results = [verify_record(path, Path(workdir), tolerance, workers) for path in records]
    if as_json:
        click.echo(json.dumps([r.to_dict() for r in results], indent=2))
    else:
        console = StdoutConsole()
        console.print(f"agreement: {tolerance} (numbers and booleans; text is not compared)")
        for result in results:
            console.print(_table(result))
            bad, new = result.disagreements(), result.not_recorded()
            n = result.n_recorded
            console.print(
                f"{result.path}: "
                + (
                    f"{len(bad)} of {n} values disagree: {first_of(bad, SHOWN)}"
                    if bad
                    else f"all {n} values agree"
                )
                + (
                    f"; {len(new)} values reported today are not in the record (added since it "
                    f"was made, not compared): {first_of(new, SHOWN)}"
                    if new
                    else ""
                ),
                soft_wrap=True,
            )
    if not all(r.agree for r in results):
        raise click.exceptions.Exit(1)

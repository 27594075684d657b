"""Whatever values a user types, a command either refuses them as a usage error (exit status
2, one line naming the option) or hands them on parsed and in range: never a traceback."""

from __future__ import annotations

import contextlib
import math
import re
import tempfile
from pathlib import Path
from unittest import mock

from cli_invoke import error_line, invoke
from hypothesis import given
from hypothesis import strategies as st

from symbench.core.common.errors import SymbenchError
from symbench.core.common.seeds import SEED_MAX
from symbench.core.plugin import registry

NUMBERS = (
    st.integers(-(2**70), 2**70).map(str)
    | st.floats().map(repr)
    | st.sampled_from(["nan", "inf", "-inf", "1e309", "0x10", " 3 ", "", "1_0"])
    | st.text(max_size=6)
)
LISTS = st.lists(NUMBERS | st.sampled_from(["sdnn", "ffnn", "hexa"]), max_size=4).map(",".join)
# relative paths inside a scratch folder, some through a file named `blocker`
PATHS = st.lists(
    st.sampled_from(["blocker", "out", "a b", "ü", ".", "x\x00y"]), min_size=1, max_size=3
).map(lambda parts: str(Path(*parts)))


def one_of_them_anything(valid: dict[str, st.SearchStrategy]) -> st.SearchStrategy:
    """Option values: valid ones, with one option (or none) given any text instead."""
    anything = {name: NUMBERS | (LISTS if name.endswith("s") else PATHS) for name in valid}
    return st.sampled_from([None, *valid]).flatmap(
        lambda chosen: st.fixed_dictionaries(
            {
                name: anything[name] if name == chosen else strategy
                for name, strategy in valid.items()
            }
        )
    )


class Reached(SymbenchError):
    """What the stand-in for the work raises: the values got through."""


@contextlib.contextmanager
def stand_in(target: str) -> mock.MagicMock:
    """`target` (module:attribute) replaced by a recorder that stops the command there."""
    with mock.patch(target.replace(":", "."), side_effect=Reached("reached")) as recorder:
        yield recorder


def refused_or_reached(result, options: tuple[str, ...]) -> bool:
    """True when the values got through; else the refusal names one of `options`."""
    if result.exit_code == 1 and error_line(result, 1) == "Error: reached":
        return True
    message = error_line(result, 2)
    named = "|".join(re.escape(option) for option in options)
    assert re.fullmatch(rf"Error: Invalid value for '({named})': \S.*", message), message
    return False


COUNTS = st.integers(0, 2**33).map(str)
RUN = {
    "--seed": COUNTS,
    "--max-steps": COUNTS,
    "--workers": COUNTS,
    "--evaluators": st.sampled_from(["torque-error", "torque-error,equivariance"]),
    "--output": PATHS,
}


@given(values=one_of_them_anything(RUN))
def test_run_values_are_refused_or_handed_on_in_range(values):
    with (
        tempfile.TemporaryDirectory() as scratch,
        contextlib.chdir(scratch),
        stand_in("symbench.core.runs.cli.run:run_spec") as run,
    ):
        Path("blocker").write_text("a file, not a folder")
        result = invoke(
            "run",
            "--model",
            "sdnn",
            "--robot",
            "hexa",
            *(f"{option}={value}" for option, value in values.items()),
        )
        names = [e.strip() for e in values["--evaluators"].split(",") if e.strip()]
        unknown = [n for n in names if n not in registry.collect("evaluators")]
        if unknown and result.exit_code == 1:  # names are checked before the plan is printed
            shown = " ".join(unknown[0].split())  # messages are one line: \r, \n become spaces
            assert error_line(result, 1).startswith(f"Error: unknown evaluator '{shown}'")
            return
        if not refused_or_reached(result, tuple(values)):
            return
        spec = run.call_args.args[0]
        assert spec.seed == int(values["--seed"]) and 0 <= spec.seed <= SEED_MAX
        assert spec.max_steps == int(values["--max-steps"]) >= 1
        assert spec.workers == int(values["--workers"]) >= 1
        assert list(spec.evaluators) == names and len(set(names)) == len(names) > 0
        assert spec.output.is_dir()  # made, and a folder: nothing in the way


@given(models=LISTS, seeds=LISTS)
def test_sweep_lists_are_refused_or_handed_on_parsed(models, seeds):
    with (
        tempfile.TemporaryDirectory() as scratch,
        contextlib.chdir(scratch),
        stand_in("symbench.core.runs.sweep:plan") as plan,
    ):
        result = invoke("sweep", f"--models={models}", "--robots=hexa", f"--seeds={seeds}")
        if refused_or_reached(result, ("--models", "--seeds")):
            parsed_models, _, _, parsed_seeds, *_ = plan.call_args.args
            assert parsed_models == [m.strip() for m in models.split(",") if m.strip()]
            assert parsed_seeds == [int(s) for s in seeds.split(",") if s.strip()]
            assert all(0 <= s <= SEED_MAX for s in parsed_seeds)


REALS = st.floats(-1e3, 1e3).map(repr)
SIM_CHECK = {
    "--inclination": REALS,
    "--heading": REALS,
    "--seconds": REALS,
    "--control-period": REALS,
}


@given(values=one_of_them_anything(SIM_CHECK))
def test_sim_check_numbers_are_refused_or_finite_and_in_range(values):
    with stand_in("symbench.core.sim.check:check") as check:
        result = invoke(
            "sim",
            "check",
            "--robot=hexa",
            *(f"{option}={value}" for option, value in values.items()),
        )
        if refused_or_reached(result, tuple(values)):
            scenario, control_period, _ = check.call_args.args  # (then the symmetry window)
            assert 0 <= scenario.inclination_deg <= 180 and math.isfinite(scenario.heading_deg)
            assert 0 < scenario.seconds < math.inf and 0 < control_period < math.inf

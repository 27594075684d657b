"""The public API for plugin authors: `from symbench import ...`.

Every promised name resolves, `import symbench` stays light, and an entry that names a
view, variant or backend that does not exist fails when it is made, reported under the name
of the plugin that made it, while the other plugins keep working.
"""

from __future__ import annotations

import json
import re
import subprocess
import sys
from pathlib import Path

import pytest
from click.testing import CliRunner

import symbench
from symbench import (
    EvaluatorEntry,
    InvalidEntryError,
    ModelEntry,
    RobotEntry,
    SplitEntry,
    hookimpl,
)
from symbench.core.cli import build_cli
from symbench.core.common.lazy_names import LazyNames
from symbench.core.data.views import schema
from symbench.core.plugin import registry
from symbench.core.plugin.host import PluginHost, set_host

STUB = Path(symbench.__file__).with_suffix(".pyi")
HEAVY = ("torch", "jax", "flax", "mujoco", "dm_control", "pandas", "pyarrow")


def test_every_public_name_resolves_and_is_documented():
    assert len(set(symbench.__all__)) == len(symbench.__all__)
    for name in symbench.__all__:
        assert getattr(symbench, name) is not None, name
        documented = re.search(rf"(?<![\w.]){re.escape(name)}(?!\w)", symbench.__doc__)
        assert documented, f"{name} is missing from the module docstring"


def test_the_stub_is_the_one_list_of_public_names():
    """`__init__.pyi` declares each name once, grouped by role; `__all__`, the docstring's
    roles and what loads on first use all come from it."""
    names = LazyNames.from_stub("symbench", STUB)
    assert symbench.__all__ == names.all
    assert [n for role in names.roles.values() for n in role] == names.all
    assert "Writing evaluators" in names.roles and "track" in names.roles["Writing evaluators"]
    assert {"__version__", "hookimpl", "model_entry", "schema"} <= set(names.all)
    assert symbench.model_entry is registry.model and symbench.schema is schema


@pytest.mark.parametrize(
    ("stub", "problem"),
    [
        ("from .a import b as b\nfrom .c import b as b\n", "'b' is declared twice"),
        ("from .a import b as b\nc = 1\n", "2: not a `from .module import name` line"),
        ("from symbench.a import b as b\n", "1: not a `from .module import name` line"),
    ],
)
def test_a_wrong_stub_fails_when_read(tmp_path, stub, problem):
    (tmp_path / "__init__.pyi").write_text(stub)
    with pytest.raises(ValueError, match=re.escape(problem)):
        LazyNames.from_stub("pkg", tmp_path / "__init__.pyi")


def test_an_unknown_name_is_an_attribute_error():
    with pytest.raises(AttributeError, match="has no attribute 'ModelEntri'"):
        _ = symbench.ModelEntri


def test_import_symbench_loads_no_heavy_library():
    code = f"import sys, symbench; print([m for m in {HEAVY!r} if m in sys.modules])"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "[]"


def test_the_command_line_registers_its_plugins_without_the_data_stack():
    """Every command, `--version` included, registers the built-in plugins: their modules
    resolve symbench's names when a run calls them, so the CLI starts in a fraction of the
    time (0.55 -> 0.38 s for `symbench --version`, measured)."""
    code = (
        "import runpy, sys\n"
        "sys.argv = ['symbench', '--version']\n"
        "try:\n    runpy.run_module('symbench', run_name='__main__')\n"
        "except SystemExit:\n    pass\n"
        f"print([m for m in {HEAVY + ('symbench.core.data.dataset',)!r} if m in sys.modules])\n"
        "print('symbench.plugins.evaluators' in sys.modules, 'symbench.plugins.zoo' in sys.modules)"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.splitlines()[-2:] == ["[]", "True True"]


def _model(**change):
    fields = (
        dict(name="m", backend="torch", view="leg_grouped", variant="acc", equivariant=True)
        | change
    )
    return ModelEntry(**fields, build=lambda dims: None)


@pytest.mark.parametrize(
    ("change", "message"),
    [
        (
            {"view": "graph"},
            "model 'm': view 'graph' is not one of leg_grouped, vector, body_graph",
        ),
        ({"variant": "accel"}, "model 'm': variant 'accel' is not one of acc, next"),
        ({"backend": "tensorflow"}, "model 'm': backend 'tensorflow' is not one of torch, jax"),
        ({"name": "my model"}, "model name 'my model' is not a name"),
        ({"name": "a/b"}, "model name 'a/b' is not a name"),
        # a record could not hold these: the run would fail only when writing it
        ({"name": "sdnn+aug"}, "model name 'sdnn+aug' is not a name"),
        ({"name": "m" * 101}, f"model name '{'m' * 101}' is not a name: use at most 100"),
        ({"name": "m\n"}, "model name 'm\\n' is not a name"),
        ({"equivariant": "yes"}, "model 'm': equivariant must be True or False"),
        ({"version": 0}, "model 'm': version must be a positive integer, got 0"),
        ({"version": True}, "model 'm': version must be a positive integer, got True"),
        ({"version": "2"}, "model 'm': version must be a positive integer, got '2'"),
        (
            {"learning_rates": {"hexa": 1.5}},
            "model 'm': learning_rates['hexa'] must be a number in (0, 1), got 1.5",
        ),
        (
            {"learning_rates": {"hexa": True}},
            "model 'm': learning_rates['hexa'] must be a number in (0, 1), got True",
        ),
        (
            {"learning_rates": {"my robot": 1e-3}},
            "model 'm': learning_rates robot name 'my robot' is not a name",
        ),
        (
            {"learning_rates": [("hexa", 1e-3)]},
            "model 'm': learning_rates must map robot names to learning rates",
        ),
    ],
)
def test_a_wrong_model_entry_fails_when_made(change, message):
    with pytest.raises(InvalidEntryError) as error:
        _model(**change)
    assert str(error.value).startswith(message)


def test_wrong_callables_and_rates_fail_when_made():
    with pytest.raises(InvalidEntryError, match="build must be callable"):
        ModelEntry("m", "torch", "leg_grouped", "acc", True, build="pkg.mod:build")
    with pytest.raises(InvalidEntryError, match=r"learning_rate must be a number in \(0, 1\)"):
        _model(learning_rate=0.0)
    with pytest.raises(InvalidEntryError, match="evaluate must be callable"):
        EvaluatorEntry("e", evaluate=None)
    with pytest.raises(InvalidEntryError, match="assign must be callable"):
        SplitEntry("s", assign=3)
    with pytest.raises(InvalidEntryError, match="spec_dir must be a path"):
        RobotEntry("r", spec_dir=None)


def test_evaluator_needs_are_checked_when_made():
    entry = EvaluatorEntry("e", evaluate=len, needs=["simulator", "variant:next"])
    assert entry.needs == ("simulator", "variant:next")  # kept as a tuple
    assert EvaluatorEntry("e", evaluate=len).needs == ()
    assert set(entry.needs) <= set(symbench.EVALUATOR_NEEDS)
    with pytest.raises(InvalidEntryError, match="evaluator 'e': need 'simulation' is not one of"):
        EvaluatorEntry("e", evaluate=len, needs=("simulation",))
    with pytest.raises(InvalidEntryError, match="needs must be a tuple of names"):
        EvaluatorEntry("e", evaluate=len, needs="simulator")
    with pytest.raises(InvalidEntryError, match="needs names one twice"):
        EvaluatorEntry("e", evaluate=len, needs=("raw", "raw"))


class Misspelt:
    """A third party's plugin whose second model names a view that does not exist."""

    @hookimpl
    def symbench_models(self):
        return [_model(name="fine"), _model(name="typo", view="leg-grouped")]


def test_a_wrong_entry_is_reported_under_its_plugin_and_breaks_nothing_else():
    host = PluginHost()
    host.load_entry_points("none")
    host.register(Misspelt(), "misspelt")
    set_host(host)
    try:
        listing = CliRunner().invoke(build_cli(), ["list", "models", "--json"])
        run = CliRunner().invoke(build_cli(), ["run", "--model", "typo", "--robot", "hexa"])
    finally:
        set_host(None)
    problem = (
        "plugin 'misspelt' failed in symbench_models: InvalidEntryError: model 'typo': "
        "view 'leg-grouped' is not one of leg_grouped, vector, body_graph"
    )
    assert listing.exit_code == 0
    assert listing.stderr.strip() == f"warning: {problem}"
    listed = {m["name"] for m in json.loads(listing.stdout)}
    assert {"sdnn", "gnn", "ffnn"} <= listed and not listed & {"fine", "typo"}
    assert run.exit_code == 1
    assert run.stderr.splitlines()[-1].endswith(f"it may be lost with what failed: {problem}")

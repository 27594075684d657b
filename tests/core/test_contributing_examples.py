"""The plugin examples of the documentation run, register what they claim to, and use only
the public API: the per-hook examples and the split plugin of docs/writing-plugins.md, the
example plugin's files as quoted there, and the complete plugin of CONTRIBUTING.md."""

from __future__ import annotations

import ast
import importlib
import re
import sys
import types
from collections.abc import Iterator
from pathlib import Path

import click
import numpy as np
import pytest
from click.testing import CliRunner

import symbench
import symbench.testing
from symbench.core.data.splits import SplitContext
from symbench.core.plugin import registry
from symbench.core.plugin.host import PluginHost, set_host

ROOT = Path(__file__).resolve().parents[2]
WRITING_PLUGINS = ROOT / "docs" / "writing-plugins.md"
CONTRIBUTING = ROOT / "CONTRIBUTING.md"
DOCUMENTS = [ROOT / "README.md", CONTRIBUTING, *sorted((ROOT / "docs").glob("*.md"))]
HOOKS = (
    "symbench_models",
    "symbench_robots",
    "symbench_evaluators",
    "symbench_splits",
    "symbench_commands",
)
PYTHON_BLOCK = re.compile(r"```python\n(.*?)```", re.S)


def section(text: str, heading: str) -> str:
    """From `heading` (a level-2 heading) to the next level-2 heading."""
    start = text.index(f"\n{heading}\n")
    end = text.find("\n## ", start + len(heading) + 2)
    return text[start : end if end >= 0 else len(text)]


def hook_examples() -> dict[str, str]:
    """The first Python block under each hook's heading in 'The hooks' section."""
    hooks = section(WRITING_PLUGINS.read_text(), "## The hooks")
    out = {}
    for hook in HOOKS:
        start = hooks.index(f"### `{hook}(")
        block = PYTHON_BLOCK.search(hooks, start)
        assert block is not None, f"no Python example under {hook}"
        out[hook] = block.group(1)
    return out


def block_named(path: Path, first_line: str) -> str:
    """The Python block of `path` whose first line is `first_line` (a file-name comment)."""
    found = [b for b in PYTHON_BLOCK.findall(path.read_text()) if b.startswith(first_line + "\n")]
    assert len(found) == 1, f"{path.name}: {len(found)} blocks start with {first_line!r}"
    return found[0]


def module_from(code: str, name: str, source: str) -> types.ModuleType:
    module = types.ModuleType(name)
    module.__file__ = str(ROOT / "documentation_example" / "__init__.py")
    exec(compile(code, source, "exec"), module.__dict__)
    return module


@pytest.fixture(scope="module")
def plugins(tmp_path_factory) -> Iterator[dict[str, types.ModuleType]]:
    """Each hook's example as the `__init__.py` of a package on sys.path, imported as an
    installed plugin is, so that what a plugin may do there (`files(__name__)`) works."""
    root = tmp_path_factory.mktemp("documented_plugins")
    for hook, code in hook_examples().items():
        (root / f"example_{hook}").mkdir()
        (root / f"example_{hook}" / "__init__.py").write_text(code)
    sys.path.insert(0, str(root))
    try:
        yield {hook: importlib.import_module(f"example_{hook}") for hook in HOOKS}
    finally:
        sys.path.remove(str(root))
        for hook in HOOKS:
            sys.modules.pop(f"example_{hook}", None)


def host_with(module: types.ModuleType) -> PluginHost:
    host = PluginHost()
    host.register(module, module.__name__)
    return host


# --- the public API only ----------------------------------------------------------------


def imports_outside_the_public_api(code: str) -> list[str]:
    """Every symbench import of `code` that is not `from symbench[.testing] import <public>`."""
    public = {"symbench": set(symbench.__all__), "symbench.testing": set(symbench.testing.__all__)}
    bad = []
    for node in ast.walk(ast.parse(code)):
        if isinstance(node, ast.Import):
            bad += [a.name for a in node.names if a.name.startswith("symbench.")]
        elif isinstance(node, ast.ImportFrom) and (node.module or "").startswith("symbench"):
            allowed = public.get(node.module or "")
            names = [a.name for a in node.names]
            if allowed is None or not set(names) <= allowed:
                bad.append(f"from {node.module} import {', '.join(names)}")
    return bad


@pytest.mark.parametrize("document", DOCUMENTS, ids=lambda p: p.name)
def test_every_example_imports_only_the_public_api(document):
    bad = []
    for code in PYTHON_BLOCK.findall(document.read_text()):
        bad += imports_outside_the_public_api(code)
    assert bad == []


def test_the_public_api_check_can_fail():
    assert imports_outside_the_public_api("from symbench.core.plugin.entries import ModelEntry")
    assert imports_outside_the_public_api("from symbench import load_dataset")
    assert imports_outside_the_public_api("import symbench.core.data")
    assert not imports_outside_the_public_api("from symbench import ModelEntry, hookimpl")


# --- the per-hook examples of docs/writing-plugins.md ------------------------------------


@pytest.mark.parametrize(
    "hook,kind",
    [
        ("symbench_models", "models"),
        ("symbench_robots", "robots"),
        ("symbench_evaluators", "evaluators"),
        ("symbench_splits", "splits"),
    ],
)
def test_collection_examples_register_an_entry(plugins, hook, kind):
    host = host_with(plugins[hook])
    entries = registry.collect(kind, host)
    assert len(entries) == 1 and host.problems == []


def test_robot_example_finds_its_folder_inside_its_package(plugins):
    (entry,) = registry.collect("robots", host_with(plugins["symbench_robots"])).values()
    package = Path(plugins["symbench_robots"].__file__).parent
    assert entry.spec_dir == package / "tripod"


def robot_registrations() -> dict[str, str]:
    """Every documented robot hook (a Python block registering a `RobotEntry` in the docs) and
    the example robot plugin's, by where it is."""
    found = {
        f"{document.name} block {i}": code
        for document in DOCUMENTS
        for i, code in enumerate(PYTHON_BLOCK.findall(document.read_text()))
        if "RobotEntry(" in code
    }
    penta = ROOT / "examples" / "symbench-penta" / "symbench_penta" / "__init__.py"
    return {**found, "symbench-penta": penta.read_text()}


def test_every_robot_example_finds_its_folder_with_importlib_resources():
    """Not `Path(__file__).parent`: a folder beside the module is the editable install's
    layout, and the docs say to use importlib.resources so that wheels work (issue 42,
    item 10: the hook example and 'Adding a robot' said different things)."""
    examples = robot_registrations()
    assert len(examples) >= 3  # the hook's example, 'Adding a robot', the penta plugin
    for where, code in examples.items():
        assert "__file__" not in code, where
        assert "from importlib.resources import files" in code, where


def test_evaluator_example_computes_its_metric(plugins):
    (entry,) = registry.collect("evaluators", host_with(plugins["symbench_evaluators"])).values()
    context = types.SimpleNamespace(predictions=lambda: np.array([[[1.0, -3.0, 2.0]]]))
    assert entry.evaluate(context) == {"max_abs_torque": 3.0}


def split_context(inclinations: list[float]) -> SplitContext:
    scenarios = tuple({"inclination_deg": inc} for inc in inclinations)
    return SplitContext(
        "toy", np.arange(len(scenarios)), scenarios, np.full(len(scenarios), 10), 6, 0
    )


def test_split_example_labels_trajectories(plugins):
    (entry,) = registry.collect("splits", host_with(plugins["symbench_splits"])).values()
    context = split_context([0, 30, 45, 90, 90, 0, 30, 60] * 3)
    labels = np.asarray(entry.assign(context))
    steep = context.values("inclination_deg").astype(float) >= 60
    assert (labels[steep] == "test").all()
    assert set(labels[~steep]) == {"train", "val"}


def test_commands_example_adds_a_command(plugins):
    group = click.Group("symbench")
    host_with(plugins["symbench_commands"]).call("symbench_commands", cli=group)
    result = CliRunner().invoke(group, ["hello"])
    assert result.exit_code == 0 and result.output.strip() == "hello from my plugin"


def test_complete_split_example_tests_on_the_steepest_slopes():
    code = block_named(WRITING_PLUGINS, "# my_splits/__init__.py")
    module = module_from(code, "my_splits", "writing-plugins.md:my_splits")
    (entry,) = registry.collect("splits", host_with(module)).values()
    context = split_context([30.0, 60.0, 90.0] * 4)
    labels = np.asarray(entry.assign(context))
    steepest = context.values("inclination_deg").astype(float) == 90.0
    assert (labels[steepest] == "test").all() and set(labels[~steepest]) == {"train", "val"}
    with pytest.raises(symbench.SymbenchError, match="single inclination"):
        entry.assign(split_context([90.0] * 6))


@pytest.mark.parametrize("name", ["__init__.py", "leg_attention.py", "leg_attention_flax.py"])
def test_the_example_plugin_is_quoted_as_it_is(name):
    path = f"examples/symbench-example-plugin/symbench_example_plugin/{name}"
    quoted = re.search(
        rf"File `{re.escape(path)}`:\n\n```python\n(.*?)```", WRITING_PLUGINS.read_text(), re.S
    )
    assert quoted is not None, f"docs/writing-plugins.md does not quote {path}"
    assert quoted.group(1) == (ROOT / path).read_text()


# --- the complete plugin of CONTRIBUTING.md ----------------------------------------------


@pytest.fixture
def my_plugin(monkeypatch) -> Iterator[types.ModuleType]:
    """CONTRIBUTING.md's package `my_plugin`, importable, and registered with the built-ins."""
    package = types.ModuleType("my_plugin")
    package.__path__ = []  # a package, so that my_plugin.network can be imported
    monkeypatch.setitem(sys.modules, "my_plugin", package)
    network = module_from(
        block_named(CONTRIBUTING, "# my_plugin/network.py"), "my_plugin.network", "network.py"
    )
    monkeypatch.setitem(sys.modules, "my_plugin.network", network)
    package.network = network
    exec(
        compile(block_named(CONTRIBUTING, "# my_plugin/__init__.py"), "__init__.py", "exec"),
        package.__dict__,
    )
    host = PluginHost()
    host.load_entry_points("none")  # the built-in robots, for robot_group("hexa")
    host.register(package, "my_plugin")
    set_host(host)
    yield package
    set_host(None)


def test_complete_plugin_registers_its_model_and_evaluator(my_plugin):
    assert set(registry.collect("models")) >= {"leg-mixer/torch"}
    assert set(registry.collect("evaluators")) >= {"worst-leg"}
    assert registry.model("leg-mixer").equivariant


def test_complete_plugin_evaluator_computes_its_metric(my_plugin):
    target = np.zeros((2, 4, 3))
    pred = target.copy()
    pred[:, 2] = 3.0  # leg 2 is off by 3 N m in every joint
    context = types.SimpleNamespace(
        predictions=lambda: pred, test=types.SimpleNamespace(target=target)
    )
    metrics = registry.evaluator("worst-leg").evaluate(context)
    assert metrics == {"worst_leg_rmse": 3.0, "rmse_per_leg": [0.0, 0.0, 3.0, 0.0]}


def test_complete_plugin_passes_its_own_tests(my_plugin):
    tests = module_from(
        block_named(CONTRIBUTING, "# tests/test_my_plugin.py"), "test_my_plugin", "tests"
    )
    tests.test_leg_mixer_is_equivariant_on_hexa()
    tests.test_leg_mixer_learns()

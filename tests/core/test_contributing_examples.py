"""The hook examples in CONTRIBUTING.md run and register what they claim to."""

from __future__ import annotations

import re
import types
from pathlib import Path

import click
import numpy as np
import pytest
from click.testing import CliRunner

from symbench.core.data.splits import SplitContext
from symbench.core.plugin import registry
from symbench.core.plugin.host import PluginHost

ROOT = Path(__file__).resolve().parents[2]
HOOKS = (
    "symbench_models",
    "symbench_robots",
    "symbench_evaluators",
    "symbench_splits",
    "symbench_commands",
)


def hook_examples() -> dict[str, str]:
    """The first Python block under each hook's heading in 'The hooks' section."""
    text = (ROOT / "CONTRIBUTING.md").read_text()
    section = text[text.index("## The hooks") : text.index("\n## ", text.index("## The hooks") + 5)]
    out = {}
    for hook in HOOKS:
        start = section.index(f"### `{hook}(")
        block = re.search(r"```python\n(.*?)```", section[start:], re.S)
        out[hook] = block.group(1)
    return out


@pytest.fixture(scope="module")
def plugins() -> dict[str, types.ModuleType]:
    modules = {}
    for hook, code in hook_examples().items():
        module = types.ModuleType(f"contributing_{hook}")
        module.__file__ = str(ROOT / "contributing_example" / "__init__.py")
        exec(compile(code, f"CONTRIBUTING.md:{hook}", "exec"), module.__dict__)
        modules[hook] = module
    return modules


def host_with(module: types.ModuleType) -> PluginHost:
    host = PluginHost()
    host.register(module, module.__name__)
    return host


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


def test_evaluator_example_computes_its_metric(plugins):
    (entry,) = registry.collect("evaluators", host_with(plugins["symbench_evaluators"])).values()
    context = types.SimpleNamespace(predictions=lambda: np.array([[[1.0, -3.0, 2.0]]]))
    assert entry.evaluate(context) == {"max_abs_torque": 3.0}


def test_split_example_labels_trajectories(plugins):
    (entry,) = registry.collect("splits", host_with(plugins["symbench_splits"])).values()
    scenarios = tuple({"inclination_deg": inc} for inc in [0, 30, 45, 90, 90, 0, 30, 60] * 3)
    context = SplitContext(
        "toy", np.arange(len(scenarios)), scenarios, np.full(len(scenarios), 10), 6, 0
    )
    labels = np.asarray(entry.assign(context))
    steep = np.array([s["inclination_deg"] >= 60 for s in scenarios])
    assert (labels[steep] == "test").all()
    assert set(labels[~steep]) == {"train", "val"}


def test_commands_example_adds_a_command(plugins):
    group = click.Group("symbench")
    host_with(plugins["symbench_commands"]).call("symbench_commands", cli=group)
    result = CliRunner().invoke(group, ["hello"])
    assert result.exit_code == 0 and result.output.strip() == "hello from my plugin"

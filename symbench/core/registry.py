"""Everything the plugins registered, keyed by name, with clear errors for unknown names."""

from __future__ import annotations

from typing import Any

from symbench.core.entries import EvaluatorEntry, ModelEntry, RobotEntry, SplitEntry
from symbench.core.errors import SymbenchError, UnknownNameError, lookup
from symbench.core.plugins import PluginHost, PluginProblem, get_host

KINDS = {
    "models": ("symbench_models", ModelEntry),
    "robots": ("symbench_robots", RobotEntry),
    "evaluators": ("symbench_evaluators", EvaluatorEntry),
    "splits": ("symbench_splits", SplitEntry),
}


def _key(entry: Any) -> str:
    """Models are registered per backend: the key is 'name' plus '/backend'."""
    return f"{entry.name}/{entry.backend}" if isinstance(entry, ModelEntry) else entry.name


def collect(kind: str, host: PluginHost | None = None) -> dict[str, Any]:
    """All entries of one kind; a wrong type or a duplicate name is a problem of that plugin."""
    hook, entry_type = lookup("kind", kind, KINDS)
    host = host or get_host()
    table: dict[str, Any] = {}
    owner: dict[str, str] = {}
    for plugin, entries in host.call(hook):
        for entry in entries:
            if not isinstance(entry, entry_type):
                host.report(PluginProblem(
                    plugin, hook, f"returned {type(entry).__name__}, expected {entry_type.__name__}"))
                continue
            key = _key(entry)
            if key in table:
                host.report(PluginProblem(
                    plugin, hook, f"{kind[:-1]} '{key}' is already registered by '{owner[key]}'"))
                continue
            table[key], owner[key] = entry, plugin
    return dict(sorted(table.items()))


def model(name: str, backend: str = "torch", host: PluginHost | None = None) -> ModelEntry:
    """The model `name` for `backend`, or an error naming the closest models."""
    table = collect("models", host)
    names = {e.name for e in table.values()}
    if name not in names:
        raise UnknownNameError("model", name, names)
    backends = sorted(e.backend for e in table.values() if e.name == name)
    if backend not in backends:
        raise SymbenchError(f"model '{name}' has no '{backend}' backend (it has {', '.join(backends)})")
    return table[f"{name}/{backend}"]


def robot(name: str, host: PluginHost | None = None) -> RobotEntry:
    return lookup("robot", name, collect("robots", host))


def evaluator(name: str, host: PluginHost | None = None) -> EvaluatorEntry:
    return lookup("evaluator", name, collect("evaluators", host))


def split(name: str, host: PluginHost | None = None) -> SplitEntry:
    return lookup("split", name, collect("splits", host))

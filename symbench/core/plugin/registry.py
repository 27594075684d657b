"""Everything the plugins registered, keyed by name, with clear errors for unknown names.

A name registered twice is an error naming both plugins and their distributions: taking
either one silently (entry points load in alphabetical order) would let any installed
package replace a built-in model and put its numbers on a board under the built-in's name.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any, NamedTuple

from symbench.core.common.errors import SymbenchError, UnknownNameError, lookup
from symbench.core.plugin.entries import EvaluatorEntry, ModelEntry, RobotEntry, SplitEntry
from symbench.core.plugin.host import (
    PluginHost,
    PluginInfo,
    PluginProblem,
    duplicate,
    get_host,
)

KINDS = {
    "models": ("symbench_models", ModelEntry),
    "robots": ("symbench_robots", RobotEntry),
    "evaluators": ("symbench_evaluators", EvaluatorEntry),
    "splits": ("symbench_splits", SplitEntry),
}


class Registration(NamedTuple):
    key: str
    entry: Any
    plugin: str  # the entry-point (or in-process) name of the plugin that registered it


def _key(entry: Any) -> str:
    """Models are registered per backend: the key is 'name' plus '/backend'."""
    return f"{entry.name}/{entry.backend}" if isinstance(entry, ModelEntry) else entry.name


def registrations(kind: str, host: PluginHost | None = None) -> list[Registration]:
    """Every entry of one kind, duplicates included; a wrong type is a problem of its plugin
    (reported, and its result left out, so that it breaks no command but its own)."""
    hook, entry_type = lookup("kind", kind, KINDS)
    host = host or get_host()
    found = []
    for plugin, entries in host.call(hook):
        if not isinstance(entries, (list, tuple)):
            wrong = f"returned {type(entries).__name__}, expected a list of {entry_type.__name__}"
            host.report(PluginProblem(plugin, hook, wrong))
            continue
        for entry in entries:
            if isinstance(entry, entry_type):
                found.append(Registration(_key(entry), entry, plugin))
            else:
                wrong = f"returned {type(entry).__name__}, expected {entry_type.__name__}"
                host.report(PluginProblem(plugin, hook, wrong))
    return found


def _registered(kind: str, host: PluginHost) -> dict[str, Registration]:
    """Every registration of one kind by key; a key registered twice is an error naming both."""
    table: dict[str, Registration] = {}
    for reg in registrations(kind, host):
        if reg.key in table:
            raise duplicate(
                kind[:-1],
                reg.key,
                str(host.info[table[reg.key].plugin]),
                str(host.info[reg.plugin]),
            )
        table[reg.key] = reg
    return table


def collect(kind: str, host: PluginHost | None = None) -> dict[str, Any]:
    """All entries of one kind by key; a key registered twice is an error naming both."""
    table = _registered(kind, host or get_host())
    return {key: table[key].entry for key in sorted(table)}


def provider(kind: str, key: str, host: PluginHost | None = None) -> PluginInfo:
    """The plugin that registered `key` of `kind` (entry point, distribution, version): what a
    record names so that the same code can be installed again, and what a problem of the
    entry (a robot folder a wheel left out) is blamed on."""
    host = host or get_host()
    registration: Registration = _find(kind[:-1], key, _registered(kind, host), host)
    return host.info[registration.plugin]


def names(host: PluginHost | None = None) -> list[dict[str, str]]:
    """Every registered name of every kind with the plugin, distribution and version behind it
    (duplicates included, so that `symbench plugins` shows both sides of a conflict)."""
    host = host or get_host()
    return [
        host.registered(kind[:-1], reg.key, reg.plugin)
        for kind in KINDS
        for reg in registrations(kind, host)
    ]


def _unknown(what: str, name: str, valid: Iterable[str], host: PluginHost) -> SymbenchError:
    """An unknown name; when plugins failed (to import, or in a hook, such as one whose entry
    named a view that does not exist), the message says one of them may have held it."""
    error = UnknownNameError(what, name, valid)
    if not host.problems:
        return error
    blamed = "; ".join(str(p) for p in host.problems)
    return SymbenchError(f"{error}; it may be lost with what failed: {blamed}")


def _find(what: str, name: str, table: dict[str, Any], host: PluginHost) -> Any:
    if name not in table:
        raise _unknown(what, name, table, host)
    return table[name]


def model(name: str, backend: str = "torch", host: PluginHost | None = None) -> ModelEntry:
    """The model `name` for `backend`, or an error naming the closest models."""
    host = host or get_host()
    table = collect("models", host)
    backends = sorted(e.backend for e in table.values() if e.name == name)
    if not backends:
        raise _unknown("model", name, {e.name for e in table.values()}, host)
    if backend not in backends:
        raise SymbenchError(
            f"model '{name}' has no '{backend}' backend (it has {', '.join(backends)})"
        )
    entry: ModelEntry = table[f"{name}/{backend}"]
    return entry


model_entry = model  # its name in the public API (`from symbench import model_entry`)


def robot(name: str, host: PluginHost | None = None) -> RobotEntry:
    host = host or get_host()
    entry: RobotEntry = _find("robot", name, collect("robots", host), host)
    return entry


def evaluator(name: str, host: PluginHost | None = None) -> EvaluatorEntry:
    host = host or get_host()
    entry: EvaluatorEntry = _find("evaluator", name, collect("evaluators", host), host)
    return entry


def split(name: str, host: PluginHost | None = None) -> SplitEntry:
    host = host or get_host()
    entry: SplitEntry = _find("split", name, collect("splits", host), host)
    return entry

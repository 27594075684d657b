"""The plugin manager: loads entry points, calls hooks one plugin at a time.

Built-in plugins are declared in symbench's own `symbench` entry-point group, exactly as a
third-party package declares its own. Each hook implementation is called separately so that
one plugin that fails to import or raises is reported by name while the others keep working.

`SYMBENCH_PLUGINS` restricts third-party loading: unset or `all` loads every installed
plugin; `none` (or empty) loads the built-ins only; a comma-separated list of entry-point
names loads the built-ins and those. A name that is not installed is an error, not a silent
no-op: a misspelt plugin would otherwise quietly drop out of a benchmark.

Names are never silently replaced: the same entry-point name from two distributions is an
error here, and the same model, robot, evaluator, split or command name from two plugins is
an error where those are collected (`registry.collect`, `cli.build_cli`), naming both.
"""

from __future__ import annotations

import os
from collections.abc import Callable
from dataclasses import dataclass, field
from importlib.metadata import EntryPoint, entry_points
from typing import Any

import pluggy

from symbench.core.common.errors import SymbenchError, UnknownNameError
from symbench.core.plugin import hookspecs

PROJECT = "symbench"
ENV_VAR = "SYMBENCH_PLUGINS"
IMPORT = "import"  # PluginProblem.where for a plugin that could not be imported


@dataclass(frozen=True)
class PluginProblem:
    """A plugin that could not be imported or raised in a hook."""

    plugin: str
    where: str
    error: str

    def __str__(self) -> str:
        if self.where == IMPORT:
            return f"plugin '{self.plugin}' failed to import: {self.error}"
        return f"plugin '{self.plugin}' failed in {self.where}: {self.error}"


@dataclass
class PluginInfo:
    name: str
    distribution: str
    version: str
    builtin: bool

    def __str__(self) -> str:
        """How messages name a plugin: entry point, then the distribution that ships it."""
        shipped_by = f"{self.distribution} {self.version}".strip()
        return f"plugin '{self.name}' ({shipped_by})"


@dataclass
class PluginHost:
    """A pluggy manager plus what it knows about where each plugin came from."""

    pm: pluggy.PluginManager = field(default_factory=lambda: _new_manager())
    info: dict[str, PluginInfo] = field(default_factory=dict)
    problems: list[PluginProblem] = field(default_factory=list)

    def register(
        self,
        plugin: Any,
        name: str,
        distribution: str = "",
        version: str = "",
        builtin: bool = False,
    ) -> None:
        """Register an in-process plugin (a module or an object with hookimpls)."""
        info = PluginInfo(name, distribution or "in-process", version, builtin)
        if name in self.info:
            raise duplicate("plugin entry point", name, str(self.info[name]), str(info))
        self.pm.register(plugin, name=name)
        self.info[name] = info

    def report(self, problem: PluginProblem) -> None:
        """Remember a plugin's failure once, however often the hook is called."""
        if problem not in self.problems:
            self.problems.append(problem)

    def load_entry_points(self, allowed: str | None = None) -> None:
        """Load the `symbench` entry points, built-ins always, others as SYMBENCH_PLUGINS says."""
        allowed = os.environ.get(ENV_VAR, "all") if allowed is None else allowed
        found = sorted(entry_points(group=PROJECT), key=lambda e: e.name)
        selected = _selection(allowed, [ep.name for ep in found])
        for ep in found:
            dist, version = _distribution(ep)
            builtin = dist == PROJECT
            if not builtin and selected is not None and ep.name not in selected:
                continue
            try:
                plugin = ep.load()
            except Exception as exc:  # a broken plugin must not take the others down
                self.report(PluginProblem(ep.name, IMPORT, _describe(exc)))
                continue
            self.register(plugin, ep.name, dist, version, builtin)

    def call(self, hook: str, **kwargs: Any) -> list[tuple[str, Any]]:
        """Call every implementation of `hook`; results as (plugin name, result) pairs."""
        return self.call_each(hook, lambda plugin: kwargs)

    def call_each(
        self, hook: str, kwargs_of: Callable[[str], dict[str, Any]]
    ) -> list[tuple[str, Any]]:
        """`call` with arguments per plugin (`kwargs_of(plugin name)`), so that what a hook
        adds to an argument can be told apart by plugin."""
        results = []
        for impl in getattr(self.pm.hook, hook).get_hookimpls():
            kwargs = kwargs_of(impl.plugin_name)
            try:
                result = impl.function(**{name: kwargs[name] for name in impl.argnames})
            except Exception as exc:
                self.report(PluginProblem(impl.plugin_name, hook, _describe(exc)))
                continue
            if result is not None:
                results.append((impl.plugin_name, result))
        return results

    def hooks_of(self, name: str) -> list[str]:
        plugin = self.pm.get_plugin(name)
        return sorted(c.name for c in (self.pm.get_hookcallers(plugin) or []))

    def registered(self, kind: str, name: str, plugin: str) -> dict[str, str]:
        """One row of `symbench plugins`' list of names: what, and who registered it."""
        info = self.info[plugin]
        return {
            "kind": kind,
            "name": name,
            "plugin": plugin,
            "distribution": info.distribution,
            "version": info.version,
        }

    def describe(self) -> dict[str, Any]:
        """JSON-ready summary: every plugin with its hooks, and every problem."""
        return {
            "plugins": [
                {
                    "name": i.name,
                    "distribution": i.distribution,
                    "version": i.version,
                    "builtin": i.builtin,
                    "hooks": self.hooks_of(i.name),
                }
                for i in sorted(self.info.values(), key=lambda i: i.name)
            ],
            "problems": [vars(p) for p in self.problems],
        }


def duplicate(what: str, name: str, first: str, second: str) -> SymbenchError:
    """The error for a name registered twice; `first` and `second` say by whom."""
    return SymbenchError(
        f"{what} '{name}' is registered twice: by {first} and by {second}; "
        f"uninstall one or leave it out of {ENV_VAR}"
    )


def _new_manager() -> pluggy.PluginManager:
    pm = pluggy.PluginManager(PROJECT)
    pm.add_hookspecs(hookspecs)
    return pm


def _distribution(ep: EntryPoint) -> tuple[str, str]:
    dist = getattr(ep, "dist", None)
    if dist is None:
        return "unknown", ""
    return dist.metadata["Name"].lower().replace("_", "-"), dist.version


def _selection(allowed: str, installed: list[str]) -> set[str] | None:
    """The entry points SYMBENCH_PLUGINS names (None: all); a name not installed is an error."""
    allowed = allowed.strip()
    if allowed == "all":
        return None
    names = set() if allowed == "none" else {a.strip() for a in allowed.split(",") if a.strip()}
    unknown = sorted(names - set(installed))
    if unknown:
        raise SymbenchError(f"{ENV_VAR}: {UnknownNameError('plugin', unknown[0], installed)}")
    return names


def _describe(exc: BaseException) -> str:
    """The exception in one line, so that each warning is one line."""
    return " ".join(f"{type(exc).__name__}: {exc}".split())


_HOST: PluginHost | None = None


def get_host() -> PluginHost:
    """The process-wide plugin host, loaded on first use."""
    global _HOST
    if _HOST is None:
        host = PluginHost()
        host.load_entry_points()  # may refuse (SYMBENCH_PLUGINS): keep no half-loaded host
        _HOST = host
    return _HOST


def set_host(host: PluginHost | None) -> None:
    """Replace the process-wide host (tests register in-process plugins this way)."""
    global _HOST
    _HOST = host

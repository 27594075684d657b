"""The plugin manager: loads entry points, calls hooks one plugin at a time.

Built-in plugins are declared in symbench's own `symbench` entry-point group, exactly as a
third-party package declares its own. Each hook implementation is called separately so that
one plugin that fails to import or raises is reported by name while the others keep working.

`SYMBENCH_PLUGINS` restricts third-party loading: unset or `all` loads every installed
plugin; `none` (or empty) loads the built-ins only; a comma-separated list of entry-point
names loads the built-ins and those.
"""

from __future__ import annotations

import os
from dataclasses import dataclass, field
from importlib.metadata import EntryPoint, entry_points
from typing import Any

import pluggy

from symbench.core import hookspecs

PROJECT = "symbench"
ENV_VAR = "SYMBENCH_PLUGINS"


@dataclass(frozen=True)
class PluginProblem:
    """A plugin that could not be imported or raised in a hook."""

    plugin: str
    where: str
    error: str

    def __str__(self) -> str:
        return f"plugin '{self.plugin}' failed in {self.where}: {self.error}"


@dataclass
class PluginInfo:
    name: str
    distribution: str
    version: str
    builtin: bool


@dataclass
class PluginHost:
    """A pluggy manager plus what it knows about where each plugin came from."""

    pm: pluggy.PluginManager = field(default_factory=lambda: _new_manager())
    info: dict[str, PluginInfo] = field(default_factory=dict)
    problems: list[PluginProblem] = field(default_factory=list)

    def register(self, plugin: Any, name: str, distribution: str = "", version: str = "",
                 builtin: bool = False) -> None:
        """Register an in-process plugin (a module or an object with hookimpls)."""
        self.pm.register(plugin, name=name)
        self.info[name] = PluginInfo(name, distribution or "(in-process)", version, builtin)

    def report(self, problem: PluginProblem) -> None:
        """Remember a plugin's failure once, however often the hook is called."""
        if problem not in self.problems:
            self.problems.append(problem)

    def load_entry_points(self, allowed: str | None = None) -> None:
        """Load the `symbench` entry points, built-ins always, others as SYMBENCH_PLUGINS says."""
        allowed = os.environ.get(ENV_VAR, "all") if allowed is None else allowed
        for ep in sorted(entry_points(group=PROJECT), key=lambda e: e.name):
            dist, version = _distribution(ep)
            builtin = dist == PROJECT
            if not builtin and not _third_party_allowed(ep.name, allowed):
                continue
            if ep.name in self.info:
                continue
            try:
                plugin = ep.load()
            except Exception as exc:  # a broken plugin must not take the others down
                self.report(PluginProblem(ep.name, "import", _describe(exc)))
                continue
            self.register(plugin, ep.name, dist, version, builtin)

    def call(self, hook: str, **kwargs: Any) -> list[tuple[str, Any]]:
        """Call every implementation of `hook`; results as (plugin name, result) pairs."""
        results = []
        for impl in getattr(self.pm.hook, hook).get_hookimpls():
            args = {name: kwargs[name] for name in impl.argnames}
            try:
                result = impl.function(**args)
            except Exception as exc:
                self.report(PluginProblem(impl.plugin_name, hook, _describe(exc)))
                continue
            if result is not None:
                results.append((impl.plugin_name, result))
        return results

    def hooks_of(self, name: str) -> list[str]:
        plugin = self.pm.get_plugin(name)
        return sorted(c.name for c in (self.pm.get_hookcallers(plugin) or []))

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


def _new_manager() -> pluggy.PluginManager:
    pm = pluggy.PluginManager(PROJECT)
    pm.add_hookspecs(hookspecs)
    return pm


def _distribution(ep: EntryPoint) -> tuple[str, str]:
    dist = getattr(ep, "dist", None)
    if dist is None:
        return "(unknown)", ""
    return dist.metadata["Name"].lower().replace("_", "-"), dist.version


def _third_party_allowed(name: str, allowed: str) -> bool:
    allowed = allowed.strip()
    if allowed in ("", "none"):
        return False
    if allowed == "all":
        return True
    return name in {a.strip() for a in allowed.split(",")}


def _describe(exc: BaseException) -> str:
    return f"{type(exc).__name__}: {exc}"


_HOST: PluginHost | None = None


def get_host() -> PluginHost:
    """The process-wide plugin host, loaded on first use."""
    global _HOST
    if _HOST is None:
        _HOST = PluginHost()
        _HOST.load_entry_points()
    return _HOST


def set_host(host: PluginHost | None) -> None:
    """Replace the process-wide host (tests register in-process plugins this way)."""
    global _HOST
    _HOST = host

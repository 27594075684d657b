"""A package's public names, declared once in its `__init__.pyi` and loaded on first use.

The stub is the single list: each public name is one `from .module import name as public`
line, grouped by role under a `# role` comment line. Type checkers and editors read the stub
as the package; the package's `__init__.py` reads it here for `__all__`, for where each name
loads from (PEP 562 `__getattr__`), and for the roles its docstring lists. Nothing is
imported until a name is used, so importing the package stays light.
"""

from __future__ import annotations

import ast
import importlib
import textwrap
from dataclasses import dataclass
from pathlib import Path
from typing import Any

WIDTH = 92  # the docstring's role listings are wrapped to this width


@dataclass(frozen=True)
class LazyNames:
    """Public name -> (module, attribute) and role -> public names, in the stub's order."""

    package: str
    targets: dict[str, tuple[str, str]]
    roles: dict[str, list[str]]
    doc: str

    @classmethod
    def from_stub(cls, package: str, stub: Path) -> LazyNames:
        """Reads the relative `from ... import ... as ...` lines of `stub` (the package's
        `__init__.pyi`); any other statement but the docstring is an error."""
        source = stub.read_text()
        lines = source.splitlines()
        tree = ast.parse(source, filename=str(stub))
        targets: dict[str, tuple[str, str]] = {}
        roles: dict[str, list[str]] = {}
        role = ""
        for node in tree.body:
            if node is tree.body[0] and isinstance(node, ast.Expr):
                continue  # the docstring
            if not (isinstance(node, ast.ImportFrom) and node.level == 1 and node.module):
                raise ValueError(f"{stub}:{node.lineno}: not a `from .module import name` line")
            above = lines[node.lineno - 2].strip() if node.lineno > 1 else ""
            if above.startswith("#"):
                role = above.lstrip("#").strip()
            for alias in node.names:
                public = alias.asname or alias.name
                if public in targets:
                    raise ValueError(f"{stub}:{node.lineno}: '{public}' is declared twice")
                targets[public] = (f"{package}.{node.module}", alias.name)
                roles.setdefault(role, []).append(public)
        return cls(package, targets, roles, ast.get_docstring(tree, clean=False) or "")

    @property
    def all(self) -> list[str]:
        return list(self.targets)

    def docstring(self) -> str:
        """The stub's docstring followed by each role and its names."""
        indent = " " * 4
        listing = [
            f"{role}\n"
            + textwrap.fill(
                ", ".join(names), WIDTH, initial_indent=indent, subsequent_indent=indent
            )
            for role, names in self.roles.items()
        ]
        return self.doc.rstrip() + "\n\n" + "\n".join(listing) + "\n"

    def load(self, name: str) -> Any:
        """The object a public name stands for, imported as `from module import attribute`
        would (an attribute of the module, else its submodule)."""
        if name not in self.targets:
            raise AttributeError(f"module '{self.package}' has no attribute '{name}'")
        module_name, attribute = self.targets[name]
        module = importlib.import_module(module_name)
        try:
            return getattr(module, attribute)
        except AttributeError:
            return importlib.import_module(f"{module_name}.{attribute}")

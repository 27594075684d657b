"""pydantic validation errors as one line: every problem with the dotted path of its field."""

from __future__ import annotations

from pydantic import ValidationError

from symbench.core.common.errors import SymbenchError


def explain(error: ValidationError, what: str) -> SymbenchError:
    """`what: field.path: problem; other.field: problem`."""
    problems = []
    for e in error.errors():
        where = ".".join(str(p) if str(p).isprintable() and str(p) else repr(p) for p in e["loc"])
        problems.append(f"{where or '(top level)'}: {e['msg']}")
    return SymbenchError(f"{what}: " + "; ".join(problems))

"""The documentation keeps up with the code: every hook has a test and a section, every
command and option is in docs/commands.md, every public name is in docs/writing-plugins.md,
the README's set-up commands are the Makefile's, and no document cites a file that is not in
the repository. Each check is shown to fail on a deliberately missing item."""

from __future__ import annotations

import inspect
import re
from collections.abc import Iterator
from pathlib import Path

import click

import symbench
from symbench.core.cli import cli
from symbench.core.plugin import hookspecs

ROOT = Path(__file__).resolve().parents[2]
README = ROOT / "README.md"
COMMANDS = ROOT / "docs" / "commands.md"
WRITING_PLUGINS = ROOT / "docs" / "writing-plugins.md"
README_MAX_LINES = 170


def hook_names() -> list[str]:
    return [
        n for n, f in inspect.getmembers(hookspecs, inspect.isfunction) if n.startswith("symbench_")
    ]


def missing_from(names: list[str], texts: list[str]) -> list[str]:
    """Names that no text mentions as a whole word (a prefix of a longer name does not count)."""
    return [n for n in names if not any(re.search(rf"\b{re.escape(n)}\b", t) for t in texts)]


def texts_of_tests() -> list[str]:
    own = Path(__file__).resolve()
    return [p.read_text() for p in (ROOT / "tests").rglob("test_*.py") if p.resolve() != own]


def hook_sections() -> list[str]:
    """The hook headings of docs/writing-plugins.md ('### `symbench_models(')."""
    return re.findall(r"^### `(symbench_\w+)\(", WRITING_PLUGINS.read_text(), re.M)


# --- hooks ---------------------------------------------------------------------------------


def test_there_are_hooks():
    assert set(hook_names()) >= {
        "symbench_models",
        "symbench_robots",
        "symbench_evaluators",
        "symbench_splits",
        "symbench_commands",
    }


def test_every_hook_has_a_section_in_writing_plugins():
    assert missing_from(hook_names(), hook_sections()) == []


def test_every_hook_has_a_test():
    assert missing_from(hook_names(), texts_of_tests()) == []


def test_the_meta_check_catches_a_new_hook():
    fake = ["symbench_teleport_robot", "symbench_model"]  # new, and a prefix of a real hook
    assert missing_from(hook_names() + fake, hook_sections()) == fake
    assert missing_from(hook_names() + fake, texts_of_tests()) == fake


# --- the public API ------------------------------------------------------------------------


def undocumented_public_names(names: list[str]) -> list[str]:
    text = WRITING_PLUGINS.read_text()
    return [n for n in names if f"`{n}`" not in text]


def test_every_public_name_is_in_writing_plugins():
    assert undocumented_public_names(list(symbench.__all__)) == []


def test_the_public_name_check_can_fail():
    assert undocumented_public_names(["teleport_robot"]) == ["teleport_robot"]


# --- commands ------------------------------------------------------------------------------


def commands(group: click.Group = cli, path: tuple[str, ...] = ()) -> Iterator:
    """(path, command) of every core command and subcommand, depth first."""
    ctx = click.Context(group)
    for name in group.list_commands(ctx):
        command = group.get_command(ctx, name)
        assert command is not None
        yield (*path, name), command
        if isinstance(command, click.Group):
            yield from commands(command, (*path, name))


def option_names(command: click.Command) -> list[str]:
    names = []
    for param in command.params:
        if isinstance(param, click.Option):
            names += [n for n in param.opts + param.secondary_opts if n.startswith("--")]
    return [n for n in names if n != "--help"]


def command_section(text: str, path: tuple[str, ...]) -> str | None:
    """From the heading '`symbench <path>`' to the next heading; None when there is none."""
    match = re.search(rf"^#+ `symbench {re.escape(' '.join(path))}`\n", text, re.M)
    if match is None:
        return None
    end = re.compile(r"^#", re.M).search(text, match.end())
    return text[match.end() : end.start() if end else len(text)]


def undocumented_commands(text: str, found: list[tuple[tuple[str, ...], list[str]]]) -> list[str]:
    """'symbench <path>' without a section, or 'symbench <path> --option' missing from it."""
    missing = []
    for path, options in found:
        body = command_section(text, path)
        if body is None:
            missing.append(f"symbench {' '.join(path)}")
            continue
        missing += [
            f"symbench {' '.join(path)} {o}" for o in options if not re.search(rf"`{o}`", body)
        ]
    return missing


def test_every_command_and_option_is_in_commands_md():
    text = COMMANDS.read_text()
    found = [(path, option_names(command)) for path, command in commands()]
    assert len(found) > 10
    assert undocumented_commands(text, found) == []
    top = text[: text.index("\n## ")]
    assert [o for o in option_names(cli) if f"`{o}`" not in top] == []


def test_the_command_check_can_fail():
    text = COMMANDS.read_text()
    assert undocumented_commands(text, [(("teleport",), [])]) == ["symbench teleport"]
    assert undocumented_commands(text, [(("run",), ["--teleport"])]) == ["symbench run --teleport"]


# --- the README ----------------------------------------------------------------------------


def make_target(name: str) -> list[str]:
    """The recipe lines and prerequisites of a Makefile target."""
    makefile = (ROOT / "Makefile").read_text()
    match = re.search(rf"^{name}:(.*)\n((?:\t.*\n)*)", makefile, re.M)
    assert match is not None, f"the Makefile has no target '{name}'"
    return [match.group(1).strip(), *(line.strip() for line in match.group(2).splitlines())]


def test_readme_set_up_commands_are_the_makefile_s():
    readme = README.read_text()
    assert "make run     # symbench run --model sdnn --robot hexa" in readme
    assert "$(VENV)/bin/symbench run --model sdnn --robot hexa" in make_target("run")
    assert "make test    #" in readme and "make test-slow" in readme
    assert "$(VENV)/bin/python -m pytest -q -n 2" in make_target("test")
    assert "-m slow" in " ".join(make_target("test-slow"))
    check = " ".join(make_target("check"))
    assert all(tool in check for tool in ("ruff check", "ruff format", "mypy", "lint-imports"))


def test_readme_is_a_guide_not_a_reference():
    assert len(README.read_text().splitlines()) <= README_MAX_LINES


# --- citations -----------------------------------------------------------------------------


def in_repository(pattern: str) -> list[Path]:
    """Files matching `pattern`, outside hidden folders (.venv, .git, caches) and the
    published records."""
    return sorted(
        p
        for p in ROOT.rglob(pattern)
        if p.is_file()
        and not any(part.startswith(".") or part == "records" for part in p.relative_to(ROOT).parts)
    )


def documents() -> list[Path]:
    return in_repository("*.md")


def dead_references(document: Path, text: str) -> list[str]:
    """Relative Markdown links and backticked repository paths that lead nowhere."""
    dead = []
    for target in re.findall(r"\]\(([^)\s]+)\)", text):
        if re.match(r"[a-z]+:", target) or target.startswith("#"):
            continue  # a web address or an anchor in the same page
        if not (document.parent / target.split("#")[0]).exists():
            dead.append(target)
    for path in re.findall(
        r"`((?:symbench|tests|robots|leaderboards|examples|docs)/[^`<>*\s]*)`", text
    ):
        if not (ROOT / path.split("::")[0]).exists():
            dead.append(path)
    return dead


def test_documents_cite_only_files_in_the_repository():
    dead = {
        str(d.relative_to(ROOT)): refs
        for d in documents()
        if (refs := dead_references(d, d.read_text()))
    }
    assert dead == {}
    assert len(documents()) >= 8


def test_the_citation_check_can_fail():
    assert dead_references(README, "see [the design](DESIGN.md) and `docs/teleport.md`") == [
        "DESIGN.md",
        "docs/teleport.md",
    ]


def test_no_file_names_documents_that_left_the_repository():
    gone = ("DESIGN" + ".md", "paper" + ".tex", "magneto-facts" + ".md", "shared/" + "reference")
    own = Path(__file__).resolve()
    files = [
        p for pattern in ("*.md", "*.py", "*.toml") for p in in_repository(pattern) if p != own
    ]
    assert [f"{p.relative_to(ROOT)}: {g}" for p in files for g in gone if g in p.read_text()] == []

"""Every rule's documentation works: its *Example* triggers the rule and its *Use instead* does not.

A section is turned into input from its ``` code blocks:

* A block without a file marker is one list, linted on its own with every rule enabled (the rule's code is
  picked from the findings, so a snippet needs no `Ende` line). Every such block of the Example must trigger
  the rule, no block of Use instead may.
* Blocks whose first line names a file (`# file: achsmds2.lis`, `; file: rfp.nc` in an NC program, or
  `<!-- file: Axis_X.xti -->` in XML) are written side by side into an empty folder, which is linted as a
  machine through the real API: an NC program against the machine of the start-up list (`--machine`),
  else through its start-up list (`hochlauf*.lis`) when it has one, the file itself when there is only
  one, otherwise the folder, with a `[[machine]]` table that makes its files one machine. The marker line stays in the file; it is a comment there. *Use instead* may
  show only the files that change: the files it does not name are those of the Example.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from pathlib import Path

import pytest

from achslint import lint
from achslint.api import LintRequest, run_lint
from achslint.core.diagnostics import Diagnostic, Severity
from achslint.linting.config import Overrides
from achslint.rules import Rule, registry

BLOCK = re.compile(r"^```[^\n]*\n(.*?)^```", re.MULTILINE | re.DOTALL)
FILE_MARKER = re.compile(
    r"^(?:#\s*file:\s*(?P<lis>\S+)|;\s*file:\s*(?P<nc>\S+)|<!--\s*file:\s*(?P<xml>\S+)\s*-->)\s*$"
)

# What a code block cannot show. A byte-order mark is invisible in a code block, so LIS006's Example says
# in prose that the list starts with one and the test puts it there.
EXAMPLE_PREFIX = {"LIS006": "\ufeff"}

RULES = list(registry().values())


def code_blocks(rule: Rule, title: str) -> list[str]:
    blocks = BLOCK.findall(rule.section(title))
    assert blocks, f"{rule.code}: the '{title}' section has no code block to run"
    return blocks


def file_name(block: str) -> str | None:
    match = FILE_MARKER.match(block.split("\n", 1)[0])
    return None if match is None else match.group("lis") or match.group("nc") or match.group("xml")


def findings(rule: Rule, title: str, folder: Callable[[], Path]) -> list[list[Diagnostic]]:
    """What achslint reports for each case (a list, or a machine) that one section of a rule's docstring shows;
    `folder()` makes the empty folder a machine is written to (most rules show lists only: none is made)."""
    blocks = code_blocks(rule, title)
    prefix = EXAMPLE_PREFIX.get(rule.code, "") if title == "Example" else ""
    names = [file_name(block) for block in blocks]
    if rule.produced_by == "dry-run":
        return [dry_run_findings(rule, blocks, names)]
    if not any(names):
        return [lint((prefix + block).encode("utf-8"), name="achsmds1.lis") for block in blocks]
    files = {name: block for name, block in zip(names, blocks, strict=True) if name}
    assert len(files) == len(blocks), (
        f"{rule.code} '{title}': name the file of every block (each once), or of none"
    )
    if title == "Use instead":  # the same machine as the Example, with the files shown here changed
        example = code_blocks(rule, "Example")
        files = {**{file_name(block): block for block in example if file_name(block)}, **files}
    tmp_path = folder()
    for name, text in files.items():
        (tmp_path / name).write_text(text, encoding="latin-1" if name.endswith(".lis") else "utf-8")
    startup = sorted(tmp_path.glob("hochlauf*.lis"))
    programs = sorted(tmp_path.glob("*.nc"))
    machine = None
    if programs:  # a homing program (LIS6xx), checked against the machine of the start-up list
        target, machine = programs[0], str(startup[0])
    elif startup:
        target = startup[0]
    elif len(files) == 1:
        target = tmp_path / next(iter(files))
    else:  # lists without their start-up list: a [[machine]] table says they are one machine
        (tmp_path / ".achslint.toml").write_text('[[machine]]\nlists = ["*"]\n', encoding="utf-8")
        target = tmp_path
    outcome = run_lint(LintRequest([str(target)], Overrides(), jobs=1, machine=machine))
    assert not outcome.errors, outcome.errors
    return [[d for result in outcome.results for d in result.diagnostics]]


def dry_run_findings(rule: Rule, blocks: list[str], names: list[str | None]) -> list[Diagnostic]:
    """A rule only the dry-run reports (LIS405): its section holds one list and one `scenario.toml`; the
    dry-run's warnings stand in for findings (code and message only)."""
    from achslint.dryrun import dry_run
    from achslint.homing.scenario import parse_input

    try:
        import tomllib
    except ModuleNotFoundError:  # Python 3.10
        import tomli as tomllib

    lists = [block for block, name in zip(blocks, names, strict=True) if name is None]
    scenarios = [block for block, name in zip(blocks, names, strict=True) if name == "scenario.toml"]
    assert len(lists) == 1 and len(scenarios) == 1, (
        f"{rule.code}: a dry-run rule shows one list and one scenario.toml"
    )
    trace = dry_run(
        lists[0].encode("latin-1"), "achsmds1.lis", parse_input(tomllib.loads(scenarios[0]))
    ).trace
    return [
        Diagnostic("achsmds1.lis", 1, 1, 1, 1, w["code"], rule.severity, w["message"]) for w in trace.warnings
    ]


@pytest.mark.parametrize("rule", RULES, ids=[rule.code for rule in RULES])
def test_example_triggers_the_rule(rule, tmp_path_factory):
    for number, found in enumerate(findings(rule, "Example", lambda: tmp_path_factory.mktemp(rule.code)), 1):
        assert rule.code in {d.code for d in found}, (
            f"{rule.code}: case {number} of its Example does not trigger it"
        )


@pytest.fixture(scope="module")
def use_instead(tmp_path_factory):
    """The findings of each rule's *Use instead*, worked out once for the two tests that read them."""
    found: dict[str, list[list[Diagnostic]]] = {}

    def of(rule: Rule) -> list[list[Diagnostic]]:
        if rule.code not in found:
            found[rule.code] = findings(rule, "Use instead", lambda: tmp_path_factory.mktemp(rule.code))
        return found[rule.code]

    return of


@pytest.mark.parametrize("rule", RULES, ids=[rule.code for rule in RULES])
def test_use_instead_does_not_trigger_the_rule(rule, use_instead):
    for number, found in enumerate(use_instead(rule), 1):
        assert rule.code not in {d.code for d in found}, (
            f"{rule.code}: case {number} of its Use instead triggers it"
        )


@pytest.mark.parametrize("rule", RULES, ids=[rule.code for rule in RULES])
def test_use_instead_is_a_correct_list(rule, use_instead):
    """What the docs recommend draws no error or warning from any rule (snippets may leave out `Ende`)."""
    for number, found in enumerate(use_instead(rule), 1):
        serious = [
            f"{d.code} {d.message}" for d in found if d.severity is not Severity.INFO and d.code != "LIS002"
        ]
        assert serious == [], f"{rule.code}: case {number} of its Use instead"

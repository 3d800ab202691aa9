"""The rule registry: every rule module of the code table (`codes.RULE_MODULES`), loaded in code order
(`registry`) or one by one as a run needs them (`rule`).

A rule is a module with `CODE`, `NAME`, `FIX` ("none", "safe", "unsafe" or
"sometimes"), `SUMMARY`, a docstring with the sections What / Why / Example /
Use instead / Reference, and one check function for each scope it takes part
in; its severity, scopes and list kinds are its line in the code table. The
check function's name says the scope and what it is given:

    check(ctx)                          LIST: one list (`context.Context`) of a kind
                                        its line in the code table names (mostly
                                        axis lists; `ALL_KINDS`: every kind with a
                                        catalogue)
    check_machine(machine)              MACHINE: one machine (`machine.resolved.
                                        Machine`): the summaries of its axis lists
                                        as linted, its start-up list and the lists
                                        that names, read once (LIS5xx)
    check_program(program, machine)     PROGRAM: a homing program read against a
                                        machine (LIS6xx)
    check_after(path, directives, enabled)
                                        AFTER: the `noqa` directives of a list or
                                        a program, after the suppression (LIS009)

Every check is a generator of diagnostics and runs in the one lint engine
(`linting.engine.run`), which also selects the rules, applies the suppressions
and the severity overrides. `achslint rule CODE` prints the docstring.
"""

from __future__ import annotations

import importlib
import re
from dataclasses import dataclass
from functools import cache, cached_property, lru_cache
from types import ModuleType

from ..core.diagnostics import Severity
from . import codes
from .codes import (
    ALL_KINDS,
    AXIS_KINDS,
    RULE_MODULES,
    Check,
    Scope,
    applies_to,
    known_codes,
    matches,
    selector_problem,
)

# The code table's names are the package's too: `from achslint.rules import Scope` reads as well as ever.
__all__ = [
    "ALL_KINDS",
    "AXIS_KINDS",
    "RULE_MODULES",
    "SECTIONS",
    "Check",
    "Rule",
    "Scope",
    "known_codes",
    "matches",
    "registry",
    "rule",
    "selector_problem",
]


SECTIONS = ("What", "Why", "Example", "Use instead", "Reference")


@dataclass(frozen=True)
class Rule:
    code: str
    name: str
    severity: Severity
    fix: str
    summary: str
    doc: str
    module: ModuleType
    checks: tuple[tuple[Scope, Check], ...] = ()  # one check per scope the rule takes part in
    parameters: tuple[str, ...] = ()  # catalogue paths (with [i]) a cross-parameter rule reads
    produced_by: str = "lint"  # "dry-run" for findings only the homing simulation can make (LIS405)
    # an error finding means the CNC does not run the homing (LIS306, LIS319, LIS328)
    refuses_homing: bool = False
    # an info finding says the check could not run (LIS317 on an axis too short for any assumed cam)
    info_when_unchecked: bool = False
    # the lower severity some of its findings have (LIS328: a torque limit configured but never sent)
    also: tuple[Severity, ...] = ()
    kinds: tuple[str, ...] = AXIS_KINDS  # the list kinds its LIST check runs for (ALL_KINDS: every kind)

    def applies_to(self, kind: str) -> bool:
        """Whether the rule's LIST check runs for a list of `kind` (a `catalogue.kinds` id)."""
        return applies_to(self.kinds, kind)

    @property
    def lists(self) -> str:
        """The lists the rule checks, for its documentation; empty for a rule that checks no single list."""
        if Scope.LIST not in self.scopes and Scope.AFTER not in self.scopes:
            return ""
        if self.kinds == ALL_KINDS:
            return "lists of every kind with a catalogue"
        if self.kinds == AXIS_KINDS:
            return "axis lists"
        return "lists of the kinds " + ", ".join(self.kinds)

    @property
    def severities(self) -> tuple[Severity, ...]:
        """Every severity the rule emits: its own, and info for "not checked" where the rule says so."""
        unchecked = (Severity.INFO,) if self.info_when_unchecked else ()
        return (self.severity, *self.also, *unchecked)

    @property
    def scopes(self) -> tuple[Scope, ...]:
        return tuple(scope for scope, _ in self.checks)

    def checker(self, scope: Scope) -> Check | None:
        """The rule's check for `scope`, or None when the rule does not look at that scope."""
        return next((check for own, check in self.checks if own is scope), None)

    @property
    def needs_whole_axis(self) -> bool:
        """Whether the rule judges parameters together, as the CNC resolves a whole axis: such a rule has
        nothing to judge in a default list on its own."""
        return bool(self.parameters)

    def section(self, title: str) -> str:
        """The text of one docstring section (one of SECTIONS: "What", "Why", ...); empty when missing."""
        return self._sections.get(title, "")

    @cached_property
    def _sections(self) -> dict[str, str]:  # read once: SARIF and the editor show every rule's sections
        texts = {}
        for title in SECTIONS:
            match = re.search(rf"^{re.escape(title)}\n-+\n(.*?)(?=^\S[^\n]*\n-+\n|\Z)", self.doc, re.M | re.S)
            texts[title] = match.group(1).strip() if match else ""
        return texts


@lru_cache(maxsize=1)
def registry() -> dict[str, Rule]:
    """Every rule, in code order (every rule module imported)."""
    return {code: rule(code) for code in known_codes()}


@cache
def rule(code: str) -> Rule:
    """One rule, its module imported on first need: a run imports only the rules it runs (the engine picks
    them by the code table's scopes and kinds), which saves a cold start the import of the others."""
    module = importlib.import_module(f"{__name__}.{codes.module_name(code)}")
    if code != module.CODE:
        raise ImportError(f"rule module {module.__name__} has the code {module.CODE}, the code table {code}")
    scopes = codes.scopes(code)
    undeclared = [scope.value for scope in Scope if scope not in scopes and hasattr(module, scope.value)]
    if undeclared:  # a check the engine would never call: the code table must name its scope
        raise ImportError(
            f"rule module {module.__name__} has {undeclared}, which the code table does not declare"
        )
    return Rule(
        code=code,
        name=module.NAME,
        severity=codes.severity(code),
        fix=module.FIX,
        summary=module.SUMMARY,
        doc=(module.__doc__ or "").strip(),
        module=module,
        checks=tuple((scope, getattr(module, scope.value)) for scope in scopes),
        parameters=tuple(getattr(module, "PARAMETERS", ())),
        produced_by=getattr(module, "PRODUCED_BY", "lint"),
        refuses_homing=getattr(module, "CNC_REFUSES_HOMING", False),
        info_when_unchecked=getattr(module, "INFO_WHEN_UNCHECKED", False),
        also=tuple(getattr(module, "ALSO_SEVERITIES", ())),
        kinds=codes.kinds(code),
    )

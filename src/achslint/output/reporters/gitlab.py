"""GitLab Code Quality report (a JSON array of issues with stable fingerprints)."""

from __future__ import annotations

import hashlib
from collections.abc import Sequence
from typing import TYPE_CHECKING, TextIO, TypedDict

from ...core.diagnostics import Severity
from .base import write_json

if TYPE_CHECKING:
    from .base import LintResult

SEVERITIES = {Severity.ERROR: "major", Severity.WARNING: "minor", Severity.INFO: "info"}


def fingerprint(path: str, code: str, anchor: str, occurrence: int) -> str:
    """Stable across unrelated edits: built from the file, the rule, what it is about and the
    occurrence number of that combination, not from the line number."""
    key = f"{path}\0{code}\0{anchor}\0{occurrence}"
    return hashlib.sha256(key.encode("utf-8", "surrogatepass")).hexdigest()  # names need not be UTF-8


class Lines(TypedDict):
    begin: int
    end: int


class Location(TypedDict):
    path: str
    lines: Lines


class Issue(TypedDict):
    """One entry of the report (GitLab's Code Quality format)."""

    type: str
    check_name: str
    description: str
    categories: list[str]
    severity: str
    fingerprint: str
    location: Location


def issues(results: Sequence[LintResult]) -> list[Issue]:
    found: list[Issue] = []
    for result in results:
        seen: dict[tuple[str, str, str], int] = {}
        for d in result.diagnostics:
            source = result.source_lines[d.line - 1].strip() if d.line - 1 < len(result.source_lines) else ""
            anchor = d.parameter or source
            key = (d.path, d.code, anchor)
            seen[key] = seen.get(key, 0) + 1
            found.append(
                {
                    "type": "issue",
                    "check_name": d.code,
                    "description": f"{d.code} {d.message}",
                    "categories": ["Bug Risk"] if d.severity is Severity.ERROR else ["Style"],
                    "severity": SEVERITIES[d.severity],
                    "fingerprint": fingerprint(d.path, d.code, anchor, seen[key]),
                    "location": {"path": d.path, "lines": {"begin": d.line, "end": d.end_line}},
                }
            )
    return found


def report(results: Sequence[LintResult], stream: TextIO, **_options: object) -> None:
    write_json(issues(results), stream)

"""Markdown for CI job pages (`--format markdown` of lint, explain and report): a compact summary that
`$GITHUB_STEP_SUMMARY`, GitLab job pages and pull-request comments render (CommonMark with tables, as
GitHub writes it).

Everything taken from a list or a file name is text, never markup: control characters are shown escaped
(`core.display.printable`) and every character Markdown or HTML would read as syntax is escaped with a
backslash, so a list value cannot open a link, a table cell or an HTML tag.
"""

from __future__ import annotations

import re
from collections import Counter
from collections.abc import Iterable, Sequence
from typing import TYPE_CHECKING

from ..core.diagnostics import Severity, rule_url
from ..core.display import printable

if TYPE_CHECKING:
    from ..core.diagnostics import Diagnostic
    from .reporters.base import LintResult

# ASCII punctuation Markdown (with GitHub's tables and strikethrough) or inline HTML could read as syntax.
_SYNTAX = re.compile(r"([\\`*_\[\]<>#|~&$])")
_AUTOLINK = re.compile(r"(?<=[A-Za-z])(:)(?=//)|(?<=www)(\.)", re.IGNORECASE)  # GitHub links these bare
WORST = 10  # findings listed in a summary; the rest are counted
ORDER = (Severity.ERROR, Severity.WARNING, Severity.INFO)


def text(value: object) -> str:
    """A value as Markdown text that reads as itself: on one line, every syntax character escaped."""
    escaped = _SYNTAX.sub(r"\\\1", " ".join(printable(str(value)).split()))
    return _AUTOLINK.sub(lambda m: "\\" + m[0], escaped)


def row(*cells: object) -> str:
    return "| " + " | ".join(text(cell) for cell in cells) + " |"


def table(header: Sequence[str], rows: Iterable[Sequence[object]], raw: Sequence[bool] = ()) -> list[str]:
    """A GitHub table; a column marked in `raw` holds Markdown made here (a link), not text."""
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    for cells in rows:
        shown = [str(c) if i < len(raw) and raw[i] else text(c) for i, c in enumerate(cells)]
        lines.append("| " + " | ".join(shown) + " |")
    return lines


def link(label: str, address: str) -> str:
    """A link to one of our own addresses (the rule docs), its label escaped."""
    return f"[{text(label)}](<{address}>)"


def counts(diagnostics: Iterable[Diagnostic]) -> Counter[Severity]:
    return Counter(d.severity for d in diagnostics)


def counts_words(found: Counter[Severity]) -> str:
    words = {Severity.ERROR: "error", Severity.WARNING: "warning", Severity.INFO: "info"}
    parts = []
    for severity in ORDER:
        number = found.get(severity, 0)
        parts.append(f"{number} {words[severity]}{'s' if number != 1 and severity != Severity.INFO else ''}")
    return ", ".join(parts)


def worst(diagnostics: Iterable[Diagnostic]) -> list[Diagnostic]:
    """The findings, the most severe first, then by file, line and code."""
    return sorted(diagnostics, key=lambda d: (-d.severity.rank, d.path, d.line, d.column, d.code))


def findings_table(results: Sequence[LintResult], docs_url: str | None, limit: int = WORST) -> list[str]:
    """The worst findings as a table (severity, rule with its docs link, where, message), the rest counted."""
    found = worst(d for r in results for d in r.diagnostics)
    if not found:
        return []
    rows = [
        (
            d.severity.value,
            link(d.code, rule_url(d.code, docs_url)),
            f"{d.path}:{d.line}:{d.column}",
            d.message,
        )
        for d in found[:limit]
    ]
    lines = table(("severity", "rule", "where", "message"), rows, raw=(False, True))
    if len(found) > limit:
        lines += ["", f"… and {len(found) - limit} more (`achslint lint` lists them all)."]
    return lines


def unreadable(results: Sequence[LintResult]) -> list[str]:
    return [f"- could not be checked: {text(r.error)}" for r in results if r.error]

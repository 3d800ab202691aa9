"""`lint --format markdown`: the counts and the worst findings as Markdown, for `$GITHUB_STEP_SUMMARY`, GitLab
job pages and pull-request comments (`achslint lint . --format markdown >> "$GITHUB_STEP_SUMMARY"`)."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, TextIO

from ..markdown import counts, counts_words, findings_table, unreadable

if TYPE_CHECKING:
    from .base import LintResult


def report(
    results: Sequence[LintResult], stream: TextIO, docs_url: str | None = None, **_options: object
) -> None:
    found = counts(d for r in results for d in r.diagnostics)
    files = len(results)
    lines = [f"## achslint: {counts_words(found)} in {files} file{'s' if files != 1 else ''}", ""]
    if not found and not any(r.error for r in results):
        lines.append("All checks passed.")
    lines += findings_table(results, docs_url)
    problems = unreadable(results)
    if problems:
        lines += ["", *problems]
    stream.write("\n".join(lines) + "\n")

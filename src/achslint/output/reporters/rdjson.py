"""reviewdog's Diagnostic Format as one JSON document (`rdjson`: a `DiagnosticResult`), for
`reviewdog -f=rdjson`.

Positions follow the format's definition (reviewdog/reviewdog, proto/rdf/reviewdog.proto): lines from 1,
columns from 1 counted in bytes of UTF-8, end exclusive. Our columns count characters, so each is
converted on the line's text (kept for this format); a fix becomes a suggestion per edit.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Any, TextIO

from ...core.diagnostics import DOCS_URL, Diagnostic, Severity, rule_url
from .base import write_json

if TYPE_CHECKING:
    from .base import LintResult

JsonObject = dict[str, Any]

SEVERITIES = {Severity.ERROR: "ERROR", Severity.WARNING: "WARNING", Severity.INFO: "INFO"}
SOURCE = {"name": "achslint", "url": DOCS_URL.rsplit("/", 1)[0]}


class _Columns:
    """Character columns of one file's lines as UTF-8 byte columns."""

    def __init__(self, lines: list[str]) -> None:
        self.lines = lines

    def position(self, line: int, column: int) -> JsonObject:
        text = self.lines[line - 1] if 0 < line <= len(self.lines) else None
        if text is None:  # no text kept for this line (none for a file without findings): as counted
            return {"line": line, "column": column}
        prefix = text[: column - 1]
        width = len(prefix.encode("utf-8", "surrogatepass")) + max(0, column - 1 - len(prefix))
        return {"line": line, "column": width + 1}

    def range(self, line: int, column: int, end_line: int, end_column: int) -> JsonObject:
        return {"start": self.position(line, column), "end": self.position(end_line, end_column)}


def diagnostic(d: Diagnostic, columns: _Columns, docs_url: str | None) -> JsonObject:
    found: JsonObject = {
        "message": d.message,
        "location": {"path": d.path, "range": columns.range(d.line, d.column, d.end_line, d.end_column)},
        "severity": SEVERITIES[d.severity],
        "code": {"value": d.code, "url": rule_url(d.code, docs_url)},
    }
    if d.fix is not None and d.fix.edits:
        found["suggestions"] = [
            {"range": columns.range(e.line, e.column, e.end_line, e.end_column), "text": e.content}
            for e in d.fix.edits
        ]
    return found


def document(results: Sequence[LintResult], docs_url: str | None = None) -> JsonObject:
    diagnostics: list[JsonObject] = []
    for result in results:
        if result.error:  # the file as a whole: no range
            diagnostics.append(
                {"message": result.error, "location": {"path": result.name}, "severity": "ERROR"}
            )
        columns = _Columns(result.source_lines)
        diagnostics.extend(diagnostic(d, columns, docs_url) for d in result.diagnostics)
    ranks = [d.severity.rank for r in results for d in r.diagnostics] + [3 for r in results if r.error]
    worst = {3: "ERROR", 2: "WARNING", 1: "INFO"}.get(max(ranks, default=0), "UNKNOWN_SEVERITY")
    return {"source": SOURCE, "severity": worst, "diagnostics": diagnostics}


def report(
    results: Sequence[LintResult], stream: TextIO, docs_url: str | None = None, **_options: object
) -> None:
    write_json(document(results, docs_url), stream)

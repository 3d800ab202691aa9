"""The stable JSON format (version 1): add keys, never rename them."""

from __future__ import annotations

from dataclasses import asdict

from ..diagnostics import Diagnostic
from . import write_json


def diagnostic_dict(d: Diagnostic) -> dict:
    fix = None
    if d.fix is not None:
        fix = {
            "applicability": d.fix.applicability,
            "description": d.fix.description,
            "remove_bom": d.fix.remove_bom,
            "edits": [asdict(edit) for edit in d.fix.edits],
        }
    return {
        "path": d.path,
        "line": d.line,
        "column": d.column,
        "end_line": d.end_line,
        "end_column": d.end_column,
        "code": d.code,
        "severity": d.severity.value,
        "message": d.message,
        "parameter": d.parameter,
        "p_axis": d.p_axis,
        "related": [
            {"path": r.path, "line": r.line, "column": r.column, "parameter": r.parameter, "message": r.message}
            for r in d.related
        ],
        "fix": fix,
        "url": d.url,
    }


def document(results) -> dict:
    diagnostics = [d for result in results for d in result.diagnostics]
    counts = {"error": 0, "warning": 0, "info": 0}
    for d in diagnostics:
        counts[d.severity.value] += 1
    return {
        "version": 1,
        "diagnostics": [diagnostic_dict(d) for d in diagnostics],
        "summary": {
            "files": len(results),
            "errors": counts["error"],
            "warnings": counts["warning"],
            "infos": counts["info"],
            "unreadable": [r.name for r in results if r.error],
        },
    }


def report(results, stream, **_options) -> None:
    write_json(document(results), stream)

"""The stable JSON format (version 1): add keys, never rename them."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, TextIO, TypedDict

from ...core.diagnostics import Diagnostic, rule_url
from .base import write_json

if TYPE_CHECKING:
    from .base import LintResult

# The document, as `SCHEMA` below describes it.


class EditData(TypedDict):
    line: int
    column: int
    end_line: int
    end_column: int
    content: str


class FixData(TypedDict):
    applicability: str
    description: str
    remove_bom: bool
    edits: list[EditData]


class RelatedData(TypedDict):
    path: str
    line: int
    column: int
    parameter: str | None
    message: str


class DiagnosticData(TypedDict):
    path: str
    line: int
    column: int
    end_line: int
    end_column: int
    code: str
    severity: str
    message: str
    parameter: str | None
    p_axis: str | None
    related: list[RelatedData]
    fix: FixData | None
    url: str


class Summary(TypedDict):
    files: int
    errors: int
    warnings: int
    infos: int
    unreadable: list[str]


class LintDocument(TypedDict):
    version: int
    diagnostics: list[DiagnosticData]
    summary: Summary


def diagnostic_dict(d: Diagnostic, docs_url: str | None = None) -> DiagnosticData:
    fix: FixData | None = None
    if d.fix is not None:
        fix = {
            "applicability": d.fix.applicability,
            "description": d.fix.description,
            "remove_bom": d.fix.remove_bom,
            "edits": [
                {
                    "line": edit.line,
                    "column": edit.column,
                    "end_line": edit.end_line,
                    "end_column": edit.end_column,
                    "content": edit.content,
                }
                for edit in d.fix.edits
            ],
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
            {
                "path": r.path,
                "line": r.line,
                "column": r.column,
                "parameter": r.parameter,
                "message": r.message,
            }
            for r in d.related
        ],
        "fix": fix,
        "url": rule_url(d.code, docs_url),
    }


def document(results: Sequence[LintResult], docs_url: str | None = None) -> LintDocument:
    diagnostics = [d for result in results for d in result.diagnostics]
    counts = {"error": 0, "warning": 0, "info": 0}
    for d in diagnostics:
        counts[d.severity.value] += 1
    return {
        "version": 1,
        "diagnostics": [diagnostic_dict(d, docs_url) for d in diagnostics],
        "summary": {
            "files": len(results),
            "errors": counts["error"],
            "warnings": counts["warning"],
            "infos": counts["info"],
            "unreadable": [r.name for r in results if r.error],
        },
    }


def report(
    results: Sequence[LintResult], stream: TextIO, docs_url: str | None = None, **_options: object
) -> None:
    write_json(document(results, docs_url), stream)


_POSITION = {"type": "integer", "minimum": 1}
_TEXT_OR_NULL = {"type": ["string", "null"]}

# The JSON Schema of this format (`achslint schema --output lint`). Version 1 only ever gains keys.
SCHEMA = {
    "$schema": "https://json-schema.org/draft/2020-12/schema",
    "$id": "https://achslint.readthedocs.io/en/latest/schemas/lint-v1.json",
    "title": "achslint lint --format json (version 1)",
    "type": "object",
    "required": ["version", "diagnostics", "summary"],
    "properties": {
        "version": {"const": 1},
        "diagnostics": {"type": "array", "items": {"$ref": "#/$defs/diagnostic"}},
        "summary": {
            "type": "object",
            "required": ["files", "errors", "warnings", "infos", "unreadable"],
            "properties": {
                "files": {"type": "integer", "minimum": 0},
                "errors": {"type": "integer", "minimum": 0},
                "warnings": {"type": "integer", "minimum": 0},
                "infos": {"type": "integer", "minimum": 0},
                "unreadable": {"type": "array", "items": {"type": "string"}},
            },
        },
    },
    "$defs": {
        "diagnostic": {
            "type": "object",
            "required": [
                "path",
                "line",
                "column",
                "end_line",
                "end_column",
                "code",
                "severity",
                "message",
                "parameter",
                "p_axis",
                "related",
                "fix",
                "url",
            ],
            "properties": {
                "path": {"type": "string"},
                "line": _POSITION,
                "column": _POSITION,
                "end_line": _POSITION,
                "end_column": _POSITION,
                "code": {"type": "string", "pattern": "^LIS[0-9]{3}$"},
                "severity": {"enum": ["error", "warning", "info"]},
                "message": {"type": "string", "minLength": 1},
                "parameter": _TEXT_OR_NULL,
                # the parameter's id in its list kind's catalogue: P-AXIS, P-CHAN, P-COMP, P-STUP ...
                "p_axis": {"type": ["string", "null"], "pattern": "^P-[A-Z]{4}-[0-9]{5}$"},
                "related": {
                    "type": "array",
                    "items": {
                        "type": "object",
                        "required": ["path", "line", "column", "parameter", "message"],
                        "properties": {
                            "path": {"type": "string"},
                            "line": _POSITION,
                            "column": _POSITION,
                            "parameter": _TEXT_OR_NULL,
                            "message": {"type": "string"},
                        },
                    },
                },
                "fix": {
                    "oneOf": [
                        {"type": "null"},
                        {
                            "type": "object",
                            "required": ["applicability", "description", "remove_bom", "edits"],
                            "properties": {
                                "applicability": {"enum": ["safe", "unsafe"]},
                                "description": {"type": "string"},
                                "remove_bom": {"type": "boolean"},
                                "edits": {
                                    "type": "array",
                                    "items": {
                                        "type": "object",
                                        "required": ["line", "column", "end_line", "end_column", "content"],
                                        "properties": {
                                            "line": _POSITION,
                                            "column": _POSITION,
                                            "end_line": _POSITION,
                                            "end_column": _POSITION,
                                            "content": {"type": "string"},
                                        },
                                    },
                                },
                            },
                        },
                    ]
                },
                "url": {"type": "string", "format": "uri"},
            },
        },
    },
}

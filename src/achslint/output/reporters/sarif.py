"""SARIF 2.1.0, as GitHub code scanning and other SARIF viewers read it."""

from __future__ import annotations

import hashlib
from collections.abc import Mapping, Sequence
from pathlib import Path, PurePosixPath
from typing import TYPE_CHECKING, Any, TextIO
from urllib.parse import quote

from ...core.diagnostics import Diagnostic, Severity, rule_url
from ...core.version import __version__
from .base import write_json

if TYPE_CHECKING:
    from ...rules import Rule
    from .base import LintResult

# The document follows the SARIF 2.1.0 schema (the tests validate it); its parts are plain JSON objects.
JsonObject = dict[str, Any]

SCHEMA = "https://json.schemastore.org/sarif-2.1.0.json"
LEVELS = {Severity.ERROR: "error", Severity.WARNING: "warning", Severity.INFO: "note"}


def artifact_uri(path: str) -> str:
    """A relative path stays relative (resolved against the checkout by viewers); absolute ones become file URIs."""
    if path.startswith("<"):
        return quote(PurePosixPath(path.strip("<>")).as_posix(), safe="/", errors="surrogateescape")
    candidate = Path(path)
    if candidate.is_absolute():
        return candidate.as_uri()
    # Percent-encoded, so that blanks or control characters in a name still make a valid URI reference.
    return quote(PurePosixPath(*candidate.parts).as_posix(), safe="/", errors="surrogateescape")


def _region(line: int, column: int, end_line: int, end_column: int) -> JsonObject:
    return {
        "startLine": line,
        "startColumn": column,
        "endLine": end_line,
        "endColumn": max(end_column, column),
    }


def _fingerprint(d: Diagnostic, occurrence: int = 1) -> str:
    """Stable across runs and line shifts: the rule, the file and what the finding is about, and which
    occurrence of that combination in the file it is (code scanning merges results that share a
    fingerprint into one alert). The first occurrence keeps the key it always had."""
    subject = d.parameter or d.message
    key = f"{d.code}\0{d.path}\0{subject}" + (f"\0{occurrence}" if occurrence > 1 else "")
    return hashlib.sha256(key.encode("utf-8", "backslashreplace")).hexdigest()[:32]


def _rules(docs_url: str | None, chosen: Mapping[str, Rule] | None) -> list[JsonObject]:
    from ...docs import rule_text
    from ...rules import registry

    rules: list[JsonObject] = []
    for rule in (registry() if chosen is None else chosen).values():
        text = rule_text(rule)
        rules.append(
            {
                "id": rule.code,
                "name": rule.name,
                "shortDescription": {"text": rule.summary},
                "fullDescription": {"text": rule.section("What") or rule.summary},
                "help": {"text": text, "markdown": text},
                "helpUri": rule_url(rule.code, docs_url),
                "defaultConfiguration": {"level": LEVELS[rule.severity]},
                "properties": {"fix": rule.fix},
            }
        )
    return rules


def document(
    results: Sequence[LintResult], docs_url: str | None = None, rules: Mapping[str, Rule] | None = None
) -> JsonObject:
    """The SARIF log; `rules` (default: every registered rule) are the rules its driver describes."""
    described = _rules(docs_url, rules)
    index = {rule["id"]: position for position, rule in enumerate(described)}
    sarif_results: list[JsonObject] = []
    seen: dict[tuple[str, str, str], int] = {}
    for result in results:
        for d in result.diagnostics:
            same = (d.code, d.path, d.parameter or d.message)
            seen[same] = seen.get(same, 0) + 1
            entry: JsonObject = {
                "ruleId": d.code,
                "ruleIndex": index.get(d.code, -1),
                "level": LEVELS[d.severity],
                "message": {"text": d.message},
                "locations": [
                    {
                        "physicalLocation": {
                            "artifactLocation": {"uri": artifact_uri(d.path)},
                            "region": _region(d.line, d.column, d.end_line, d.end_column),
                        },
                        **(
                            {"logicalLocations": [{"name": d.parameter, "kind": "variable"}]}
                            if d.parameter
                            else {}
                        ),
                    }
                ],
                "partialFingerprints": {"achslint/v1": _fingerprint(d, seen[same])},
            }
            if d.related:
                entry["relatedLocations"] = [
                    {
                        "id": number,
                        "physicalLocation": {
                            "artifactLocation": {"uri": artifact_uri(r.path)},
                            "region": {"startLine": r.line, "startColumn": r.column},
                        },
                        "message": {"text": r.message or (r.parameter or "related")},
                    }
                    for number, r in enumerate(d.related, 1)
                ]
            if d.p_axis:
                entry["properties"] = {"p_axis": d.p_axis}
            sarif_results.append(entry)
    invocation: JsonObject = {"executionSuccessful": not any(r.error for r in results)}
    notifications = [{"level": "error", "message": {"text": r.error}} for r in results if r.error]
    if notifications:
        invocation["toolExecutionNotifications"] = notifications
    return {
        "$schema": SCHEMA,
        "version": "2.1.0",
        "runs": [
            {
                "tool": {
                    "driver": {
                        "name": "achslint",
                        "version": __version__,
                        "informationUri": rule_url("index", docs_url).split("#", 1)[0],
                        "rules": described,
                    }
                },
                # Our columns count characters; without this readers would take UTF-16 code units.
                "columnKind": "unicodeCodePoints",
                "invocations": [invocation],
                "results": sarif_results,
            }
        ],
    }


def report(
    results: Sequence[LintResult], stream: TextIO, docs_url: str | None = None, **_options: object
) -> None:
    write_json(document(results, docs_url), stream)

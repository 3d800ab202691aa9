"""GitLab Code Quality report (a JSON array of issues with stable fingerprints)."""

from __future__ import annotations

import hashlib
import os
from collections.abc import Sequence
from pathlib import Path, PurePosixPath
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


def project_path(path: str) -> str:
    """A path as GitLab places it in the project: relative to `$CI_PROJECT_DIR` (outside a GitLab job, the
    working directory) with `/` between the parts, for a file inside it; anything else as it was shown.

    GitLab matches a Code Quality location against the files of the merge request, so an absolute path
    (`achslint lint "$CI_PROJECT_DIR/listen"`) would show nothing, and its fingerprint would change with
    the runner's build folder."""
    if path.startswith("<"):
        return path  # standard input
    project = os.environ.get("CI_PROJECT_DIR") or None
    candidate = Path(path)
    if not candidate.is_absolute():
        if project is None:
            return path  # already relative to the working directory
        candidate = Path.cwd() / candidate
    base = Path(project or Path.cwd())
    for inside, root in ((candidate, base), (candidate.resolve(), base.resolve())):  # then through links
        try:
            relative = Path(os.path.normpath(inside)).relative_to(os.path.normpath(root))
        except ValueError:
            continue
        return PurePosixPath(*relative.parts).as_posix()
    return path


def issues(results: Sequence[LintResult]) -> list[Issue]:
    found: list[Issue] = []
    shown: dict[str, str] = {}
    for result in results:
        seen: dict[tuple[str, str, str], int] = {}
        for d in result.diagnostics:
            source = result.source_lines[d.line - 1].strip() if d.line - 1 < len(result.source_lines) else ""
            anchor = d.parameter or source
            path = shown.get(d.path) or shown.setdefault(d.path, project_path(d.path))
            key = (path, d.code, anchor)
            seen[key] = seen.get(key, 0) + 1
            found.append(
                {
                    "type": "issue",
                    "check_name": d.code,
                    "description": f"{d.code} {d.message}",
                    "categories": ["Bug Risk"] if d.severity is Severity.ERROR else ["Style"],
                    "severity": SEVERITIES[d.severity],
                    "fingerprint": fingerprint(path, d.code, anchor, seen[key]),
                    "location": {"path": path, "lines": {"begin": d.line, "end": d.end_line}},
                }
            )
    return found


def report(results: Sequence[LintResult], stream: TextIO, **_options: object) -> None:
    write_json(issues(results), stream)

"""`# noqa` suppressions in lists, and in the comments of NC homing programs.

* End of line: `# noqa: LIS302` or `# noqa: LIS302, LIS303` after a value, also
  inside a `(` comment (`( fast cam search  noqa: LIS303`); a bare `noqa`
  suppresses every diagnostic on that line.
* File level: a comment line `# achslint: noqa: LIS401` suppresses the codes in
  the whole file; `# achslint: noqa` alone suppresses everything.
* NC programs (LIS6xx): the same words inside the block's comment,
  `N20 G01 Z5 (noqa: LIS606)` or `N20 G01 Z5 ; noqa: LIS606`, and a comment line
  `; achslint: noqa: LIS606` (or `(achslint: noqa: LIS606)`) for the whole program.

Each directive in a list remembers what it suppressed, so directives that
suppress nothing can be reported (LIS009); in programs they are not checked.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from . import syntax
from .diagnostics import Diagnostic

# A code is letters and a digit, then letters or digits: `LIS3O2` (a letter O) is read whole and reported
# as an unknown code (LIS009), not as `LIS3` followed by text.
_CODE = r"[A-Za-z]+[0-9][A-Za-z0-9]*"
_CODES = rf"(?P<codes>{_CODE}(?:\s*,\s*{_CODE})*)"
LINE_NOQA = re.compile(rf"(?<![\w:])noqa(?::\s*{_CODES})?", re.IGNORECASE)
FILE_NOQA = re.compile(rf"^#\s*achslint:\s*noqa(?::\s*{_CODES})?\s*$", re.IGNORECASE)
PROGRAM_FILE_NOQA = re.compile(rf"^(?:;|\()\s*achslint:\s*noqa(?::\s*{_CODES})?\s*\)?\s*$", re.IGNORECASE)


@dataclass
class Directive:
    line: syntax.Line
    column: int
    end_column: int
    codes: list[str] | None  # None: every code
    file_level: bool = False
    used: set[str] = field(default_factory=set)

    def covers(self, code: str) -> bool:
        return self.codes is None or code in self.codes


def _codes(match: re.Match[str]) -> list[str] | None:
    text = match.group("codes")
    return None if text is None else [c.strip().upper() for c in text.split(",")]


def directives(file: syntax.ListFile) -> list[Directive]:
    found: list[Directive] = []
    for line in file.lines:
        if line.kind == syntax.COMMENT:
            match = FILE_NOQA.match((line.comment or "").strip())
            if match:
                start = line.path_column
                found.append(Directive(line, start, line.end_column, _codes(match), file_level=True))
            continue
        if line.kind == syntax.ASSIGNMENT:
            if line.rest is not None:
                trailing = line.rest
            elif line.value is not None and line.value.startswith(("#", "(")):
                trailing = line.value + line.sep2  # a suppression comment where the value would be
            else:
                continue
            match = LINE_NOQA.search(trailing)
            if match:  # columns are worked out only for the rare line that has a directive
                offset = line.rest_column if line.rest is not None else line.value_column
                found.append(Directive(line, offset + match.start(), offset + match.end(), _codes(match)))
    return found


def apply(diagnostics: list[Diagnostic], found: list[Directive]) -> list[Diagnostic]:
    """Drop suppressed diagnostics, recording on each directive which codes it used."""
    by_line: dict[int, list[Directive]] = {}
    file_level = [d for d in found if d.file_level]
    for directive in found:
        if not directive.file_level:
            by_line.setdefault(directive.line.number, []).append(directive)
    kept: list[Diagnostic] = []
    for diagnostic in diagnostics:
        suppressor = next((d for d in by_line.get(diagnostic.line, ()) if d.covers(diagnostic.code)), None)
        if suppressor is None:
            suppressor = next((d for d in file_level if d.covers(diagnostic.code)), None)
        if suppressor is None:
            kept.append(diagnostic)
        else:
            suppressor.used.add(diagnostic.code)
    return kept


def apply_in_program(diagnostics: list[Diagnostic], lines: list[str]) -> list[Diagnostic]:
    """Drop the findings of an NC program (`lines`: its text) that a `noqa` in a comment suppresses."""
    whole: list[list[str] | None] = []  # codes of the file-level directives (None: every code)
    on_line: dict[int, list[str] | None] = {}
    for number, text in enumerate(lines, 1):
        match = PROGRAM_FILE_NOQA.match(text.strip())
        if match:
            whole.append(_codes(match))
            continue
        starts = [at for at in (text.find("("), text.find(";")) if at >= 0]
        found = LINE_NOQA.search(text, min(starts)) if starts else None
        if found:
            on_line[number] = _codes(found)

    def suppressed(diagnostic: Diagnostic) -> bool:
        directives = [*whole, *([on_line[diagnostic.line]] if diagnostic.line in on_line else [])]
        return any(codes is None or diagnostic.code in codes for codes in directives)

    return [diagnostic for diagnostic in diagnostics if not suppressed(diagnostic)]

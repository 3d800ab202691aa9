"""`noqa` suppressions: one model for lists and for the comments of NC homing programs.

* Lists, end of line: `# noqa: LIS302` or `# noqa: LIS302, LIS303` after a value, also
  inside a `(` comment (`( fast cam search  noqa: LIS303`); a bare `noqa`
  suppresses every diagnostic on that line.
* Lists, file level: a comment line `# achslint: noqa: LIS401` suppresses the codes in
  the whole file; `# achslint: noqa` alone suppresses everything.
* NC programs (LIS6xx): the same words inside the block's comment,
  `N20 G01 Z5 (noqa: LIS606)` or `N20 G01 Z5 ; noqa: LIS606`, and a comment line
  `; achslint: noqa: LIS606` (or `(achslint: noqa: LIS606)`) for the whole program.

Both are read into `Suppressions`: directives (`core.diagnostics.Directive`) with their place, which apply
the same way (a directive on the finding's line first, then one for the whole file) and remember what they
suppressed, so the ones that suppress nothing can be reported (LIS009) in lists and programs alike.
"""

from __future__ import annotations

import re
from collections.abc import Iterable
from dataclasses import dataclass, field

from ..core.diagnostics import Diagnostic, Directive, Edit
from ..syntax import parser as syntax

# A code is letters and a digit, then letters or digits: `LIS3O2` (a letter O) is read whole and reported
# as an unknown code (LIS009), not as `LIS3` followed by text.
_CODE = r"[A-Za-z]+[0-9][A-Za-z0-9]*"
_CODES = rf"(?P<codes>{_CODE}(?:\s*,\s*{_CODE})*)"


class _NoqaPattern:
    """A case-blind pattern that holds the word `noqa`, compiled when a text first holds that word: most lists
    have no `noqa`, and compiling the three patterns was 1.5 % of a cold `achslint lint`. A text without
    the word matches none of them, so it is answered without the pattern."""

    def __init__(self, source: str) -> None:
        self.source = source
        self._pattern: re.Pattern[str] | None = None

    def _compiled(self) -> re.Pattern[str]:
        if self._pattern is None:
            self._pattern = re.compile(self.source, re.IGNORECASE)
        return self._pattern

    def search(self, text: str, pos: int = 0) -> re.Match[str] | None:
        return self._compiled().search(text, pos) if "noqa" in text.lower() else None

    def match(self, text: str) -> re.Match[str] | None:
        return self._compiled().match(text) if "noqa" in text.lower() else None


LINE_NOQA = _NoqaPattern(rf"(?<![\w:])noqa(?::\s*{_CODES})?")
FILE_NOQA = _NoqaPattern(rf"^#\s*achslint:\s*noqa(?::\s*{_CODES})?\s*$")
PROGRAM_FILE_NOQA = _NoqaPattern(rf"^(?:;|\()\s*achslint:\s*noqa(?::\s*{_CODES})?\s*\)?\s*$")


@dataclass
class Suppressions:
    """The `noqa` directives of one list or program (`path`: its name in findings)."""

    path: str
    directives: list[Directive] = field(default_factory=list)

    @classmethod
    def of_list(cls, file: syntax.ListFile, path: str) -> Suppressions:
        return cls(path, list(_list_directives(file)))

    @classmethod
    def of_program(cls, lines: Iterable[str], path: str) -> Suppressions:
        """The directives in the comments of an NC program (`lines`: its text, line by line)."""
        return cls(path, list(_program_directives(lines)))

    def apply(self, diagnostics: list[Diagnostic]) -> list[Diagnostic]:
        """The diagnostics no directive suppresses; each directive records the codes it suppressed."""
        if not self.directives:
            return diagnostics
        by_line: dict[int, list[Directive]] = {}
        whole = [d for d in self.directives if d.file_level]
        for directive in self.directives:
            if not directive.file_level:
                by_line.setdefault(directive.line, []).append(directive)
        kept: list[Diagnostic] = []
        for diagnostic in diagnostics:
            suppressor = next(
                (d for d in by_line.get(diagnostic.line, ()) if d.covers(diagnostic.code)), None
            )
            if suppressor is None:
                suppressor = next((d for d in whole if d.covers(diagnostic.code)), None)
            if suppressor is None:
                kept.append(diagnostic)
            else:
                suppressor.used.add(diagnostic.code)
        return kept


def _codes(match: re.Match[str]) -> list[str] | None:
    text = match.group("codes")
    return None if text is None else [c.strip().upper() for c in text.split(",")]


def _list_directives(file: syntax.ListFile) -> Iterable[Directive]:
    for line in file.lines:
        if line.kind == syntax.COMMENT:
            match = FILE_NOQA.match((line.comment or "").strip())
            if match:
                yield Directive(
                    line.number, line.path_column, line.end_column, _codes(match), file_level=True
                )
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
                yield Directive(line.number, offset + match.start(), offset + match.end(), _codes(match))


def _program_directives(lines: Iterable[str]) -> Iterable[Directive]:
    for number, text in enumerate(lines, 1):
        stripped = text.strip()
        match = PROGRAM_FILE_NOQA.match(stripped)
        if match:
            start = len(text) - len(text.lstrip()) + 1
            yield Directive(number, start, start + len(stripped), _codes(match), file_level=True)
            continue
        starts = [at for at in (text.find("("), text.find(";")) if at >= 0]
        found = LINE_NOQA.search(text, min(starts)) if starts else None
        if found:
            yield Directive(number, found.start() + 1, found.end() + 1, _codes(found))


def comment_marker(file: syntax.ListFile) -> str:
    """The comment a list writes after its values: `(` or `#`, whichever most of its trailing comments use
    (`#` for a list without any)."""
    counts = {"(": 0, "#": 0}
    for line in file.lines:
        if line.kind == syntax.ASSIGNMENT and line.rest and line.rest[0] in counts:
            counts[line.rest[0]] += 1
    return "(" if counts["("] > counts["#"] else "#"


NUMBERS = (syntax.INT, syntax.HEX, syntax.REAL, syntax.REFERENCE)  # after these `#` starts a comment too


def noqa_edits(file: syntax.ListFile, wanted: dict[int, list[str]]) -> list[Edit]:
    """The edits that suppress `wanted` (line number -> codes) where they are reported: on an assignment the
    codes join the line's `noqa` (or its comment, or a new comment in the list's style: `#` only after a
    number or a reference, where the CNC reads it as one; `(` after text); a finding on any other line
    (a syntax error, `End`, a missing `Ende`, the BOM) joins the file-level `# achslint: noqa` line, added
    at the top when there is none. Codes a directive already names are left out, and a bare `noqa` covers
    everything: applying the edits a second time changes nothing."""
    marker = comment_marker(file)
    edits: list[Edit] = []
    whole: list[str] = []
    for number, codes in sorted(wanted.items()):
        line = file.lines[number - 1] if 1 <= number <= len(file.lines) else None
        if line is None or line.kind != syntax.ASSIGNMENT or not line.path_ok or line.value is None:
            whole += codes
            continue
        edit = _line_edit(line, codes, marker)
        if edit is not None:
            edits.append(edit)
    if whole:
        edit = _file_edit(file, whole)
        if edit is not None:
            edits.append(edit)
    return edits


def _missing(codes: list[str], named: str | None) -> str:
    """`codes` not among those a directive names (`named`: its codes as written), unique, in code order."""
    have = {code.strip().upper() for code in (named or "").split(",")}
    return ", ".join(sorted({code for code in codes if code not in have}))


def _line_edit(line: syntax.Line, codes: list[str], marker: str) -> Edit | None:
    value = line.value or ""
    in_value = line.rest is None and value.startswith(("#", "("))  # a comment where the value would be
    trailing = (value + line.sep2) if in_value else (line.rest or "")
    start = line.value_column if in_value else line.rest_column
    existing = LINE_NOQA.search(trailing)
    if existing and existing.group("codes") is None:
        return None  # a bare noqa suppresses everything already
    if existing:
        added = _missing(codes, existing.group("codes"))
        at = start + existing.end()
        return Edit(line.number, at, line.number, at, f", {added}") if added else None
    end = line.end_column
    # Text after a symbol or string that is no `(` comment is read with the value (LIS007): the codes go into
    # a `(` comment of their own after it.
    text_after_a_string = (
        line.rest is not None and not line.rest.startswith("(") and line.value_kind not in NUMBERS
    )
    if text_after_a_string:
        return Edit(line.number, end, line.number, end, f"  ( noqa: {_missing(codes, None)}")
    if line.rest is not None or in_value:
        return Edit(line.number, end, line.number, end, f"  noqa: {_missing(codes, None)}")
    here = marker if marker == "(" or line.value_kind in NUMBERS else "("
    return Edit(line.number, end, line.number, end, f"  {here} noqa: {_missing(codes, None)}")


def _file_edit(file: syntax.ListFile, codes: list[str]) -> Edit | None:
    for line in file.lines:
        if line.kind != syntax.COMMENT:
            continue
        text = (line.comment or "").rstrip()
        match = FILE_NOQA.match(text.strip())
        if match is None:
            continue
        if match.group("codes") is None:
            return None
        added = _missing(codes, match.group("codes"))
        at = len(line.indent) + len(text) + 1
        return Edit(line.number, at, line.number, at, f", {added}") if added else None
    newline = file.lines[0].newline if file.lines and file.lines[0].newline else "\n"
    return Edit(1, 1, 1, 1, f"# achslint: noqa: {_missing(codes, None)}{newline}")

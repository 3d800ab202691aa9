"""`lint --fix`: apply the fixes that rules attach to their diagnostics.

Fixes are edits on the decoded text (1-based line/column, end exclusive), plus
the removal of a UTF-8 byte-order mark. Only diagnostics that survived the
`noqa` suppressions carry fixes here, so a suppressed finding is never fixed.
Safe fixes are applied by default, unsafe ones only when asked. Fixing repeats
(lint, fix, lint again) until nothing fixable is left, so a second run finds
nothing to do; overlapping edits wait for the next round.
"""

from __future__ import annotations

from dataclasses import dataclass

from .decode import SourceText, decode
from .linter import FileResult, FileSettings, check_bytes
from .syntax import parse_text

MAX_ROUNDS = 10


@dataclass
class FixOutcome:
    data: bytes  # the fixed bytes (the input when nothing changed)
    fixed: int  # number of diagnostics fixed
    result: FileResult  # diagnostics of the fixed bytes


def _offsets(text: str) -> list[int]:
    """Character offset of the start of every line (as the parser numbers them)."""
    return parse_text(text).offsets()


def apply_edits(source: SourceText, fixes) -> tuple[SourceText, int]:
    """Apply non-overlapping fixes; returns the new source and how many fixes went in."""
    text = source.text
    starts = _offsets(text)
    bom = source.bom
    spans = []
    applied = 0
    for fix in fixes:
        if fix.remove_bom:
            if bom:
                bom = False
                applied += 1
            continue
        ranges = [(starts[e.line - 1] + e.column - 1, starts[e.end_line - 1] + e.end_column - 1, e.content)
                  for e in fix.edits]
        if any(a < end and start < b for start, end, _ in ranges for a, b, _ in spans):
            continue  # overlaps an edit already taken: next round
        spans.extend(ranges)
        applied += 1
    for start, end, content in sorted(spans, key=lambda span: span[0], reverse=True):
        text = text[:start] + content + text[end:]
    return SourceText(text, source.encoding, bom), applied


def fix_bytes(data: bytes, name: str, settings: FileSettings | None = None, *, unsafe: bool = False) -> FixOutcome:
    """Fix what can be fixed; the result holds the diagnostics that remain."""
    allowed = {"safe", "unsafe"} if unsafe else {"safe"}
    fixed = 0
    result = check_bytes(data, name, settings)
    for _ in range(MAX_ROUNDS):
        if result.error:
            break
        fixes = [d.fix for d in result.diagnostics if d.fix is not None and d.fix.applicability in allowed]
        if not fixes:
            break
        source, applied = apply_edits(decode(data), fixes)
        new_data = source.encode()
        if not applied or new_data == data:
            break
        fixed += applied
        data = new_data
        result = check_bytes(data, name, settings)
    return FixOutcome(data, fixed, result)

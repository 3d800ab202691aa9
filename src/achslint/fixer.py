"""`lint --fix`: apply the fixes that rules attach to their diagnostics.

Fixes are edits on the decoded text (1-based line/column, end exclusive), plus
the removal of a UTF-8 byte-order mark. Only diagnostics that survived the
`noqa` suppressions carry fixes here, so a suppressed finding is never fixed.
Safe fixes are applied by default, unsafe ones only when asked. Fixing repeats
(lint, fix, lint again) until nothing fixable is left, so a second run finds
nothing to do; overlapping edits wait for the next round.

A fix a rule calls safe is applied as safe only when it keeps what the machine
does (ruff's meaning of safe): after it, the resolved axis (after the CNC's
corrections) is the same except for the parameter of the corrected finding, and
no finding appears that was not there before. A symbol typo fixed into a homing
type the drive does not support, or a misspelt name fixed into a parameter that
then takes effect with another value, fails that test and becomes unsafe.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Iterable
from dataclasses import dataclass, replace

from .decode import SourceText, decode
from .diagnostics import Diagnostic, Fix
from .linter import FileResult, FileSettings, lint_file
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


def apply_edits(source: SourceText, fixes: Iterable[Fix]) -> tuple[SourceText, int]:
    """Apply non-overlapping fixes; returns the new source and how many fixes went in."""
    text = source.text
    starts = _offsets(text)
    bom = source.bom
    spans: list[tuple[int, int, str]] = []
    applied = 0
    for fix in fixes:
        if fix.remove_bom:
            if bom:
                bom = False
                applied += 1
            continue
        ranges = [
            (starts[e.line - 1] + e.column - 1, starts[e.end_line - 1] + e.end_column - 1, e.content)
            for e in fix.edits
        ]
        if any(a < end and start < b for start, end, _ in ranges for a, b, _ in spans):
            continue  # overlaps an edit already taken: next round
        spans.extend(ranges)
        applied += 1
    for start, end, content in sorted(spans, key=lambda span: span[0], reverse=True):
        text = text[:start] + content + text[end:]
    return SourceText(text, source.encoding, bom), applied


def behaviour(data: bytes, name: str) -> dict[str, str]:
    """What the CNC ends up with: every parameter the list sets, with the value used after corrections."""
    from .resolved import resolve_bytes

    axis = resolve_bytes(data, name)
    return {path: repr(axis.get(path)) for path in axis.set_paths()}


def keeps_behaviour(
    data: bytes, name: str, settings: FileSettings | None, diagnostic: Diagnostic, before: FileResult
) -> bool:
    """Whether `diagnostic`'s fix changes nothing but the corrected finding (see the module docstring)."""
    if diagnostic.fix is None:
        return False
    source, applied = apply_edits(decode(data), [diagnostic.fix])
    if not applied:
        return False
    new_data = source.encode()
    after = lint_file(new_data, name, settings)
    if after.error:
        return False
    old = Counter((d.code, d.parameter) for d in before.diagnostics)
    old[(diagnostic.code, diagnostic.parameter)] -= 1
    new = Counter((d.code, d.parameter) for d in after.diagnostics)
    if new - old:
        return False  # a finding that was not there before
    from .resolved import resolve_bytes

    was, now = resolve_bytes(data, name), resolve_bytes(new_data, name)
    paths = set(was.set_paths()) | set(now.set_paths())
    changed = {path for path in paths if repr(was.get(path)) != repr(now.get(path))}
    return changed <= {diagnostic.parameter}


def _demoted(result: FileResult, unsafe: set[int]) -> None:
    """Mark the fixes that failed the behaviour test as unsafe in what is reported."""
    for index in unsafe:
        d = result.diagnostics[index]
        if d.fix is None:
            continue
        d.fix = replace(
            d.fix, applicability="unsafe", description=d.fix.description + " (changes what the CNC does)"
        )


def fix_bytes(
    data: bytes, name: str, settings: FileSettings | None = None, *, unsafe: bool = False
) -> FixOutcome:
    """Fix what can be fixed; the result holds the diagnostics that remain."""
    fixed = 0
    result = lint_file(data, name, settings)
    for _ in range(MAX_ROUNDS):
        if result.error:
            break
        risky = {
            i
            for i, d in enumerate(result.diagnostics)
            if d.fix is not None
            and d.fix.applicability == "safe"
            and not d.fix.remove_bom
            and not keeps_behaviour(data, name, settings, d, result)
        }
        _demoted(result, risky)
        allowed = {"safe", "unsafe"} if unsafe else {"safe"}
        fixes = [d.fix for d in result.diagnostics if d.fix is not None and d.fix.applicability in allowed]
        if not fixes:
            break
        source, applied = apply_edits(decode(data), fixes)
        new_data = source.encode()
        if not applied or new_data == data:
            break
        fixed += applied
        data = new_data
        result = lint_file(data, name, settings)
    if not result.error:
        _demoted(
            result,
            {
                i
                for i, d in enumerate(result.diagnostics)
                if d.fix is not None
                and d.fix.applicability == "safe"
                and not keeps_behaviour(data, name, settings, d, result)
            },
        )
    return FixOutcome(data, fixed, result)

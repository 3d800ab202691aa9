"""`lint --add-noqa`: switch achslint on for a list as it is today (ruff's way to adopt a linter on legacy
code), by writing a `noqa` for every finding where it is reported; fix them later, one code at a time.

Only the list's own text changes, and only where a directive goes (`suppression.noqa_edits`): every other
byte, the encoding, the BOM and each line break stay. Findings a `noqa` in the list cannot suppress are left
as they are: those of the machine rules (LIS5xx, about several lists at once), and LIS009 (an unused `noqa`
is removed, not suppressed). XML files are never rewritten.
"""

from __future__ import annotations

from ..core.decode import decode
from ..core.diagnostics import Diagnostic, Fix
from ..syntax.parser import parse_text
from .fixer import apply_edits
from .suppression import noqa_edits

NOT_SUPPRESSED = ("LIS009",)


def add_noqa(data: bytes, diagnostics: list[Diagnostic], name: str) -> tuple[bytes, int]:
    """The list with a `noqa` for each of `diagnostics` (those of this list, from a lint of these bytes),
    and how many lines got a new or longer directive."""
    wanted: dict[int, list[str]] = {}
    for d in diagnostics:
        if d.path == name and d.code not in NOT_SUPPRESSED:
            wanted.setdefault(d.line, []).append(d.code)
    if not wanted:
        return data, 0
    source = decode(data)
    edits = noqa_edits(parse_text(source.text, name), wanted)
    if not edits:
        return data, 0
    changed, applied = apply_edits(source, [Fix("safe", "noqa", (edit,)) for edit in edits])
    return changed.encode(), applied

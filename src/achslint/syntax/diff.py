"""A unified diff of two versions of a list, as `fmt --diff` and `lint --fix --diff` show it."""

from __future__ import annotations

import difflib

from ..core.decode import decode
from . import parser as syntax

NO_NEWLINE = "\\ No newline at end of file\n"


def unified_diff(before: bytes, after: bytes, name: str, label: str = "formatted") -> str:
    """A unified diff of two versions of a list; a last line without a line break is marked as `diff` marks it."""
    old = syntax.split_lines(decode(before).text, keepends=True)
    new = syntax.split_lines(decode(after).text, keepends=True)
    out = []
    for row in difflib.unified_diff(old, new, f"{name} (original)", f"{name} ({label})"):
        out.append(row)
        if not row.endswith(("\n", "\r")):
            out.append("\n" + NO_NEWLINE)
    return "".join(out)

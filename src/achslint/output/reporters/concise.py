"""`path:line:col: CODE [severity] message` — one line per diagnostic, for grep and editors."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, TextIO

from ...core.display import printable

if TYPE_CHECKING:
    from .base import LintResult


def report(results: Sequence[LintResult], stream: TextIO, **_options: object) -> None:
    for result in results:
        if result.error:
            continue
        for d in result.diagnostics:
            stream.write(
                printable(f"{d.path}:{d.line}:{d.column}: {d.code} [{d.severity.value}] {d.message}") + "\n"
            )

"""Human output: each diagnostic with a code frame and a caret under the fault."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, TextIO

from ...core.diagnostics import Diagnostic, Severity
from ...core.display import printable

if TYPE_CHECKING:
    from .base import LintResult

_STYLE = {Severity.ERROR: "bold red", Severity.WARNING: "bold yellow", Severity.INFO: "bold cyan"}


def _frame(lines: list[str], d: Diagnostic) -> list[tuple[str, str]]:
    """(gutter, text) rows: the faulty line and one line of context before it."""
    rows: list[tuple[str, str]] = []
    first = max(d.line - 1, 1)
    width = len(str(d.line))
    for number in range(first, d.line + 1):
        if number - 1 < len(lines):
            rows.append((f"{number:>{width}} │ ", printable(lines[number - 1].expandtabs(1))))
    return rows


def _caret(line: str, d: Diagnostic) -> str:
    """Carets under the faulty span, placed by what is shown (escapes are wider than the character)."""
    shown = line.expandtabs(1)  # a tab is one column in positions and one blank on screen
    end = d.end_column if d.end_line == d.line else len(shown) + 1
    before = printable(shown[: d.column - 1])
    span = printable(shown[d.column - 1 : end - 1])
    return " " * len(before) + "^" * max(len(span), 1)


def report(
    results: Sequence[LintResult],
    stream: TextIO,
    *,
    color: bool = False,
    sources: dict[str, list[str]] | None = None,
    **_options: object,
) -> None:
    from rich.console import Console
    from rich.text import Text

    console = Console(
        file=stream,
        force_terminal=color,
        no_color=not color,
        highlight=False,
        soft_wrap=True,
        width=max(80, 200),
    )
    sources = sources or {}
    total = {"error": 0, "warning": 0, "info": 0}
    for result in results:
        lines = sources.get(result.name, [])
        for d in result.diagnostics:
            total[d.severity.value] += 1
            head = Text()
            head.append(f"{printable(d.path)}:{d.line}:{d.column}: ", style="bold")
            head.append(f"{d.code} ", style=_STYLE[d.severity])
            head.append(f"{d.severity.value}: ", style=_STYLE[d.severity])
            head.append(printable(d.message))
            console.print(head)
            for gutter, text in _frame(lines, d):
                console.print(Text(gutter, style="blue") + Text(text))
            if lines and d.line - 1 < len(lines):
                width = len(str(d.line))
                caret = _caret(lines[d.line - 1], d)
                console.print(Text(" " * width + " │ ", style="blue") + Text(caret, style=_STYLE[d.severity]))
            for related in d.related:
                console.print(
                    Text(f"  related: {printable(related.path)}:{related.line}:{related.column}", style="dim")
                    + Text(printable(f" {related.parameter or ''} {related.message}".rstrip()), style="dim")
                )
            if d.fix is not None:
                console.print(
                    Text(f"  fix ({d.fix.applicability}): {printable(d.fix.description)}", style="green")
                )
            console.print()
    summary = ", ".join(f"{count} {name}{'s' if count != 1 else ''}" for name, count in total.items())
    files = len(results)
    console.print(Text(f"{files} file{'s' if files != 1 else ''} checked: {summary}", style="bold"))

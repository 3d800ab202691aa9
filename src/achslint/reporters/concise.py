"""`path:line:col: CODE [severity] message` — one line per diagnostic, for grep and editors."""

from __future__ import annotations

from ..display import printable


def report(results, stream, **_options) -> None:
    for result in results:
        if result.error:
            continue
        for d in result.diagnostics:
            stream.write(
                printable(f"{d.path}:{d.line}:{d.column}: {d.code} [{d.severity.value}] {d.message}") + "\n"
            )

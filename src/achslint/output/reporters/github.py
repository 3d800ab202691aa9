"""GitHub Actions workflow commands: each diagnostic becomes an annotation on its line."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, TextIO

from ...core.diagnostics import Severity
from ...core.display import printable

if TYPE_CHECKING:
    from .base import LintResult

COMMANDS = {Severity.ERROR: "error", Severity.WARNING: "warning", Severity.INFO: "notice"}


def _data(text: str) -> str:
    """Workflow-command data: GitHub's own escapes for %, CR and LF; other control characters as `\\x1b`."""
    return printable(text.replace("%", "%25").replace("\r", "%0D").replace("\n", "%0A"))


def _property(text: str) -> str:
    return _data(text).replace(":", "%3A").replace(",", "%2C")


def report(results: Sequence[LintResult], stream: TextIO, **_options: object) -> None:
    for result in results:
        if result.error:
            stream.write(f"::error file={_property(result.name)}::{_data(result.error)}\n")
        for d in result.diagnostics:
            properties = [
                f"file={_property(d.path)}",
                f"line={d.line}",
                f"col={d.column}",
                f"endLine={d.end_line}",
            ]
            if d.end_line == d.line:
                properties.append(f"endColumn={d.end_column}")
            properties.append(f"title={_property(f'achslint {d.code}')}")
            stream.write(
                f"::{COMMANDS[d.severity]} {','.join(properties)}::{_data(f'{d.code} {d.message}')}\n"
            )

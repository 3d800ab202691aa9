"""Azure Pipelines logging commands: each finding a `##vso[task.logissue ...]` line, shown on the run's
summary and in the log at its file and line.

Azure knows two types, error and warning: an error finding is an error, a warning or an info finding a
warning (its message says `info`). Values are escaped as the agent unescapes them: `%` as `%AZP25`, line
breaks as `%0D`/`%0A`, and in properties also `;` and `]`.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, TextIO

from ...core.diagnostics import Severity
from ...core.display import printable

if TYPE_CHECKING:
    from .base import LintResult

TYPES = {Severity.ERROR: "error", Severity.WARNING: "warning", Severity.INFO: "warning"}


def _data(text: str) -> str:
    """The message part: the agent's escapes for %, CR and LF; other control characters as `\\x1b`."""
    return printable(text.replace("%", "%AZP25").replace("\r", "%0D").replace("\n", "%0A"))


def _property(text: str) -> str:
    return _data(text).replace(";", "%3B").replace("]", "%5D")


def report(results: Sequence[LintResult], stream: TextIO, **_options: object) -> None:
    for result in results:
        if result.error:
            stream.write(
                f"##vso[task.logissue type=error;sourcepath={_property(result.name)}]{_data(result.error)}\n"
            )
        for d in result.diagnostics:
            properties = ";".join(
                [
                    f"type={TYPES[d.severity]}",
                    f"sourcepath={_property(d.path)}",
                    f"linenumber={d.line}",
                    f"columnnumber={d.column}",
                    f"code={d.code}",
                ]
            )
            said = "" if d.severity is not Severity.INFO else " (info)"
            stream.write(f"##vso[task.logissue {properties}]{_data(f'{d.code}{said} {d.message}')}\n")

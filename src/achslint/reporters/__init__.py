"""Output formats: a small registry from format name to a report function.

Every reporter takes the per-file results and a text stream. Machine formats
use only the standard library and never colour their output.
"""

from __future__ import annotations

import importlib
from collections.abc import Sequence
from typing import TYPE_CHECKING, Any, Protocol, TextIO

if TYPE_CHECKING:
    from ..diagnostics import Diagnostic


class LintResult(Protocol):
    """What a reporter reads of one file's result (`linter.FileResult`)."""

    @property
    def name(self) -> str: ...
    @property
    def diagnostics(self) -> list[Diagnostic]: ...
    @property
    def error(self) -> str | None: ...  # the file could not be read at all
    @property
    def source_lines(self) -> list[str]: ...
    @property
    def fail_on(self) -> str: ...  # the lowest severity that fails the run for this file


class Reporter(Protocol):
    """`report(results, stream, **options)`: the options a format does not use are ignored (`color`,
    `sources` for code frames, `docs_url`)."""

    def __call__(self, results: Sequence[LintResult], stream: TextIO, **options: Any) -> None: ...


REPORTERS = {
    "full": "full",
    "concise": "concise",
    "json": "json_format",
    "sarif": "sarif",
    "github": "github",
    "gitlab": "gitlab",
    "junit": "junit",
}


def write_json(document: object, stream: TextIO) -> None:
    """The machine formats that are JSON (json, sarif, gitlab) write through here: strict JSON, one document."""
    from ..display import json_text

    stream.write(json_text(document) + "\n")


def get(name: str) -> Reporter:
    """The `report(results, stream, **options)` function of a format."""
    module = importlib.import_module(f"{__name__}.{REPORTERS[name]}")
    report: Reporter = module.report
    return report

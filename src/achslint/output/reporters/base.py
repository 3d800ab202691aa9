"""What every output format reads and how the JSON formats write: kept apart from the registry in
`__init__.py`, which loads the formats by name."""

from __future__ import annotations

from typing import TYPE_CHECKING, Protocol, TextIO

if TYPE_CHECKING:
    from ...core.diagnostics import Diagnostic


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


def write_json(document: object, stream: TextIO) -> None:
    """The machine formats that are JSON (json, sarif, gitlab) write through here: strict JSON, one document."""
    from ...core.display import json_text

    stream.write(json_text(document) + "\n")

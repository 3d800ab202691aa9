"""Output formats: a small registry from format name to a report function.

Every reporter takes the per-file results and a text stream. Machine formats
use only the standard library and never colour their output.
"""

from __future__ import annotations

import importlib
from collections.abc import Sequence
from typing import TYPE_CHECKING, Any, Protocol, TextIO


class Reporter:
    """An output format: the module with its `report` function, and what the report needs.

    A plain class, not a dataclass: every lint loads this registry, and making a dataclass at import
    costs more than the rest of the module."""

    __slots__ = ("module", "needs_source", "text")

    def __init__(self, module: str, *, text: bool = False, needs_source: bool = False) -> None:
        self.module = module
        self.text = text  # for people: `--statistics` replaces it, the closing summary lines follow it
        self.needs_source = (
            needs_source  # shows the lines of the list (the linter keeps them only when asked)
        )


if TYPE_CHECKING:
    from .base import LintResult


class ReportFunction(Protocol):
    """`report(results, stream, **options)`: the options a format does not use are ignored (`color`,
    `sources` for code frames, `docs_url`)."""

    def __call__(self, results: Sequence[LintResult], stream: TextIO, **options: Any) -> None: ...


REPORTERS = {
    "full": Reporter("full", text=True, needs_source=True),
    "concise": Reporter("concise", text=True),
    "json": Reporter("json_format"),
    "sarif": Reporter("sarif"),
    "github": Reporter("github"),
    "gitlab": Reporter("gitlab", needs_source=True),
    "junit": Reporter("junit"),
    "rdjson": Reporter("rdjson", needs_source=True),  # columns in UTF-8 bytes: counted on the lines
    "azure": Reporter("azure"),
    "markdown": Reporter("markdown"),
}


def get(name: str) -> ReportFunction:
    """The `report(results, stream, **options)` function of a format."""
    module = importlib.import_module(f"{__name__}.{REPORTERS[name].module}")
    report: ReportFunction = module.report
    return report

"""Output formats: a small registry from format name to a report function.

Every reporter takes the per-file results and a text stream. Machine formats
use only the standard library and never colour their output.
"""

from __future__ import annotations

import importlib
from dataclasses import dataclass


@dataclass(frozen=True)
class Reporter:
    """An output format: the module with its `report` function, and what the report needs."""

    module: str
    text: bool = False  # for people: `--statistics` replaces it, the closing summary lines follow it
    needs_source: bool = False  # shows the lines of the list (the linter keeps them only when asked)


REPORTERS = {
    "full": Reporter("full", text=True, needs_source=True),
    "concise": Reporter("concise", text=True),
    "json": Reporter("json_format"),
    "sarif": Reporter("sarif"),
    "github": Reporter("github"),
    "gitlab": Reporter("gitlab", needs_source=True),
    "junit": Reporter("junit"),
}


def write_json(document, stream) -> None:
    """The machine formats that are JSON (json, sarif, gitlab) write through here: strict JSON, one document."""
    from ..display import json_text

    stream.write(json_text(document) + "\n")


def get(name: str):
    """The `report(results, stream, **options)` function of a format."""
    module = importlib.import_module(f"{__name__}.{REPORTERS[name].module}")
    return module.report

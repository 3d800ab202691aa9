"""Output formats: a small registry from format name to a report function.

Every reporter takes the per-file results and a text stream. Machine formats
use only the standard library and never colour their output.
"""

from __future__ import annotations

import importlib

REPORTERS = {
    "full": "full",
    "concise": "concise",
    "json": "json_format",
    "sarif": "sarif",
    "github": "github",
    "gitlab": "gitlab",
    "junit": "junit",
}


def write_json(document, stream) -> None:
    """The machine formats that are JSON (json, sarif, gitlab) write through here: strict JSON, one document."""
    from ..display import json_text

    stream.write(json_text(document) + "\n")


def get(name: str):
    """The `report(results, stream, **options)` function of a format."""
    module = importlib.import_module(f"{__name__}.{REPORTERS[name]}")
    return module.report

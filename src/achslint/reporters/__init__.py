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


def get(name: str):
    """The `report(results, stream, **options)` function of a format."""
    module = importlib.import_module(f"{__name__}.{REPORTERS[name]}")
    return module.report

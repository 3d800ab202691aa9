"""The lint output formats under their first name: they live in `achslint.output.reporters` now.

Kept so that code written against `achslint.reporters` (the registry, `get`, a format module such as
`sarif`) goes on working; nothing in the package imports this name.
"""

from __future__ import annotations

from ..output.reporters import (
    REPORTERS,
    Reporter,
    ReportFunction,
    base,
    concise,
    full,
    get,
    github,
    gitlab,
    json_format,
    junit,
    sarif,
)

__all__ = [
    "REPORTERS",
    "ReportFunction",
    "Reporter",
    "base",
    "concise",
    "full",
    "get",
    "github",
    "gitlab",
    "json_format",
    "junit",
    "sarif",
]

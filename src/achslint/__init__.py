"""achslint: parse, validate and lint TwinCAT 3 CNC / ISG CNC axis parameter lists.

The library functions are those of `achslint.api`, re-exported here. The package import stays light: the
API module (and the stages it composes) loads on the first use of one of them.

    import achslint
    axis = achslint.load("achsmds1.lis")          # typed AxisParameters (FileNotFoundError if missing)
    diagnostics = achslint.lint("achsmds1.lis")   # list[Diagnostic]
    diagnostics = achslint.lint_text(text, filename="achsmds1.lis")
    axis = achslint.loads(text); text = achslint.dumps(axis)
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from .core.version import __version__

if TYPE_CHECKING:
    from .api import dry_run, dumps, explain, format_text, lint, lint_text, load, loads

__all__ = ["__version__", "dry_run", "dumps", "explain", "format_text", "lint", "lint_text", "load", "loads"]


def __getattr__(name: str) -> Any:
    """`achslint.lint` and the other names of `__all__`: the functions of `achslint.api` themselves."""
    if name in __all__:
        from . import api

        value = getattr(api, name)
        globals()[name] = value
        return value
    raise AttributeError(f"module 'achslint' has no attribute {name!r}")

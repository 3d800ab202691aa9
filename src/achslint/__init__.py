"""achslint: parse, validate and lint TwinCAT 3 CNC / ISG CNC axis parameter lists.

The package import is kept light; the library functions load their stages on
first use:

    import achslint
    axis = achslint.load("achsmds1.lis")          # typed AxisParameters (FileNotFoundError if missing)
    diagnostics = achslint.lint("achsmds1.lis")   # list[Diagnostic]
    diagnostics = achslint.lint_text(text, filename="achsmds1.lis")
    axis = achslint.loads(text); text = achslint.dumps(axis)
"""

from __future__ import annotations

import sys
import types
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from os import PathLike

    from .diagnostics import Diagnostic

__version__ = "0.1.0"

__all__ = ["__version__", "dry_run", "dumps", "explain", "format_text", "lint", "lint_text", "load", "loads"]


if TYPE_CHECKING:
    from .explain import ListReport


def load(
    source: str | PathLike[str] | bytes,
    *,
    defaults: str | PathLike[str] | bytes | None = None,
    strict: bool = False,
) -> Any:
    """Parse a list (a path, or bytes) into a typed `AxisParameters` model (the resolved axis);
    `strict=True` raises a pydantic ValidationError listing every error-level finding."""
    from .api import load as _load

    return _load(source, defaults=defaults, strict=strict)


def loads(text: str, *, defaults: str | None = None, strict: bool = False) -> Any:
    """`load` for the text of a list (and of its default list)."""
    from .api import loads as _loads

    return _loads(text, defaults=defaults, strict=strict)


def dumps(model: Any) -> str:
    """The text of a list in the canonical layout that `loads` reads back into an equal model."""
    from .api import dumps as _dumps

    return _dumps(model)


def lint(
    source: str | PathLike[str] | bytes,
    *,
    select: list[str] | None = None,
    ignore: list[str] | None = None,
    name: str | None = None,
) -> list[Diagnostic]:
    """Lint a list (a path, or bytes) and return its diagnostics."""
    from .api import lint as _lint

    return _lint(source, select=select, ignore=ignore, name=name)


def lint_text(
    text: str, *, filename: str = "<string>", select: list[str] | None = None, ignore: list[str] | None = None
) -> list[Diagnostic]:
    """Lint the text of a list and return its diagnostics (reported under `filename`)."""
    from .api import lint_text as _lint_text

    return _lint_text(text, filename=filename, select=select, ignore=ignore)


def explain(source: str | PathLike[str] | bytes, *, gear: int = 0) -> ListReport:
    """The homing explanation of a list, as `achslint explain FILE --format json` prints it."""
    from .api import explain as _explain

    return _explain(source, gear=gear)


def dry_run(
    source: str | PathLike[str] | bytes, scenario: dict[str, Any] | None = None, *, gear: int = 0
) -> Any:
    """Simulate the homing of a list; the result's `.trace` holds phases, events and outcome."""
    from .api import dry_run as _dry_run

    return _dry_run(source, scenario, gear=gear)


def format_text(text: str) -> str:
    """The text of a list as `achslint fmt` writes it (whitespace only)."""
    from .api import format_text as _format_text

    return _format_text(text)


class _Package(types.ModuleType):
    """The package module: loading the submodule `achslint.explain` must not replace the function
    `achslint.explain` (Python sets a package attribute for each submodule it loads). The submodule stays
    available as usual (`from achslint.explain import explain_list`)."""

    def __setattr__(self, name: str, value: Any) -> None:
        if name == "explain" and isinstance(value, types.ModuleType):
            return
        super().__setattr__(name, value)


sys.modules[__name__].__class__ = _Package

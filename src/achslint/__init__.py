"""achslint: parse, validate and lint TwinCAT 3 CNC / ISG CNC axis parameter lists.

The library functions are those of `achslint.api`, re-exported here. The package import stays light: the
API module (and the stages it composes) loads on the first use of one of them.

    import achslint
    axis = achslint.load("achsmds1.lis")          # typed AxisParameters (FileNotFoundError if missing)
    diagnostics = achslint.lint("achsmds1.lis")   # list[Diagnostic]; a folder or hochlauf.lis: the machine
    diagnostics = achslint.lint_text(text, filename="achsmds1.lis")
    axis = achslint.loads(text); text = achslint.dumps(axis)
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from .core.version import __version__

if TYPE_CHECKING:
    from .api import (
        ConfigError,
        Diagnostic,
        DryRunRefused,
        LintFailed,
        MachineError,
        OutputIsInput,
        ScenarioError,
        Severity,
        UnreadableInput,
        dry_run,
        dumps,
        explain,
        format_text,
        lint,
        lint_paths,
        lint_text,
        load,
        loads,
    )

__all__ = [  # noqa: RUF022 (grouped: the functions, what they return, what they raise)
    "__version__",
    "dry_run",
    "dumps",
    "explain",
    "format_text",
    "lint",
    "lint_paths",
    "lint_text",
    "load",
    "loads",
    "Diagnostic",
    "Severity",
    "ConfigError",
    "DryRunRefused",
    "LintFailed",
    "MachineError",
    "OutputIsInput",
    "ScenarioError",
    "UnreadableInput",
]


def __getattr__(name: str) -> Any:
    """`achslint.lint` and the other names of `__all__`: the functions (and the types and exceptions they
    use) of `achslint.api` themselves."""
    if name in __all__:
        from . import api

        value = getattr(api, name)
        globals()[name] = value
        return value
    raise AttributeError(f"module 'achslint' has no attribute {name!r}")

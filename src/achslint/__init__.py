"""achslint: parse, validate and lint TwinCAT 3 CNC / ISG CNC axis parameter lists.

The package import is kept light; the library functions load their stages on
first use:

    import achslint
    axis = achslint.load("achsmds1.lis")          # typed AxisParameters
    diagnostics = achslint.lint("achsmds1.lis")   # list[Diagnostic]
"""

__version__ = "0.1.0"

__all__ = ["__version__", "load", "lint", "lint_text"]


def load(source, *, defaults=None, strict=False):
    """Parse a list (path, bytes or text) into a typed `AxisParameters` model (the resolved axis);
    `strict=True` raises a pydantic ValidationError listing every error-level finding."""
    from .api import load as _load

    return _load(source, defaults=defaults, strict=strict)


def lint(source, *, select=None, ignore=None, name=None):
    """Lint a list (path, bytes or text) and return its diagnostics."""
    from .api import lint as _lint

    return _lint(source, select=select, ignore=ignore, name=name)


def lint_text(text, *, filename="<string>", select=None, ignore=None):
    """Lint the text of a list and return its diagnostics (reported under `filename`)."""
    from .api import lint_text as _lint_text

    return _lint_text(text, filename=filename, select=select, ignore=ignore)

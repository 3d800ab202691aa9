"""The language server (`achslint server`): diagnostics, hover, completion, code actions,
formatting, outline and definitions for axis lists in any LSP editor.

Needs the `lsp` extra (pygls 2 and lsprotocol; in the achslint checkout `pip install '.[lsp]'`).
"""

from __future__ import annotations

MISSING = "the language server needs the `lsp` extra: in the achslint checkout, pip install '.[lsp]'"


def available() -> bool:
    try:
        import lsprotocol  # noqa: F401
        import pygls.lsp.server  # noqa: F401 - pygls 2 (1.x has no pygls.lsp.server)
    except ImportError:
        return False
    return True

"""The lint engine: one readable loop from bytes to sorted diagnostics."""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

from .context import Context, Options
from .decode import UnreadableInput
from .diagnostics import Diagnostic, Severity
from .rules import matches, registry
from .syntax import parse_bytes


@dataclass
class Selection:
    """Which rules run: ruff-style select / extend-select / ignore by code or prefix."""

    select: list[str] | None = None
    extend_select: list[str] = field(default_factory=list)
    ignore: list[str] = field(default_factory=list)

    def enabled(self, code: str) -> bool:
        chosen = self.select if self.select else ["ALL"]
        if not (matches(code, chosen) or matches(code, self.extend_select)):
            return False
        return not matches(code, self.ignore)


@dataclass
class FileResult:
    name: str
    diagnostics: list[Diagnostic]
    error: str | None = None  # the file could not be read or decoded at all
    source_lines: list[str] = field(default_factory=list)  # kept for code frames when there are findings


def check_bytes(data: bytes, name: str, selection: Selection | None = None, options: Options | None = None) -> FileResult:
    """Lint the bytes of one list; unreadable input becomes a result with `error` set."""
    try:
        file = parse_bytes(data, name)
    except UnreadableInput as exc:
        return FileResult(name, [], f"{name}: {exc}")
    ctx = Context(name, file, options or Options())
    selection = selection or Selection()
    diagnostics: list[Diagnostic] = []
    for code, rule in registry().items():
        if selection.enabled(code):
            diagnostics.extend(rule.check(ctx))
    diagnostics.sort(key=Diagnostic.sort_key)
    lines = [line.body for line in file.lines] if diagnostics else []
    return FileResult(name, diagnostics, None, lines)


def lint_bytes(data: bytes, name: str, selection: Selection | None = None, options: Options | None = None) -> list[Diagnostic]:
    """Diagnostics for the bytes of one list. Raises `UnreadableInput` for UTF-16/32 input."""
    result = check_bytes(data, name, selection, options)
    if result.error:
        raise UnreadableInput(result.error)
    return result.diagnostics


def lint_path(path: Path, name: str | None = None, selection: Selection | None = None, options: Options | None = None) -> FileResult:
    display = name or str(path)
    try:
        data = path.read_bytes()
    except OSError as exc:
        return FileResult(display, [], f"cannot read {display}: {exc.strerror or exc}")
    return check_bytes(data, display, selection, options)


def worst(diagnostics: list[Diagnostic]) -> Severity | None:
    return max((d.severity for d in diagnostics), key=lambda s: s.rank, default=None)

"""The library API the CLI and tests call: lint files and load typed models."""

from __future__ import annotations

import fnmatch
import os
from dataclasses import dataclass, field
from pathlib import Path

from .context import Options
from .linter import FileResult, Selection, check_bytes, lint_bytes, lint_path


@dataclass
class LintRequest:
    paths: list[str]
    select: list[str] | None = None
    extend_select: list[str] = field(default_factory=list)
    ignore: list[str] = field(default_factory=list)
    unknown_parameters: str = "warn"
    include: str = "achsmds*.lis"
    stdin_filename: str | None = None
    cycle_time_us: int = 1000
    repeatability_tolerance_um: float = 20.0

    @property
    def selection(self) -> Selection:
        return Selection(self.select, self.extend_select, self.ignore)

    @property
    def options(self) -> Options:
        return Options(
            unknown_parameters=self.unknown_parameters,
            cycle_time_us=self.cycle_time_us,
            repeatability_tolerance_um=self.repeatability_tolerance_um,
        )


@dataclass
class LintOutcome:
    results: list[FileResult]
    errors: list[str]

    @property
    def sources(self) -> dict[str, list[str]]:
        return {r.name: r.source_lines for r in self.results if r.source_lines}


def discover(paths: list[str], include: str) -> tuple[list[Path | str], list[str]]:
    """Expand directories (recursively, by the include pattern); keep files and `-` as given."""
    found: list[Path | str] = []
    errors: list[str] = []
    for raw in paths:
        if raw == "-":
            found.append("-")
            continue
        path = Path(raw)
        if path.is_dir():
            matches = []
            for root, dirs, files in os.walk(path):
                dirs[:] = sorted(d for d in dirs if not d.startswith("."))
                matches.extend(Path(root) / f for f in files if fnmatch.fnmatch(f.lower(), include.lower()))
            found.extend(sorted(matches))
        elif path.exists():
            found.append(path)
        else:
            errors.append(f"{raw}: no such file or directory")
    return found, errors


def run_lint(request: LintRequest, stdin=None) -> LintOutcome:
    targets, errors = discover(request.paths, request.include)
    results: list[FileResult] = []
    selection, options = request.selection, request.options
    for target in targets:
        if target == "-":
            name = request.stdin_filename or "<stdin>"
            data = stdin.read() if stdin is not None else b""
            result = check_bytes(data, name, selection, options)
        else:
            result = lint_path(target, str(target), selection, options)
        if result.error:
            errors.append(result.error)
        results.append(result)
    return LintOutcome(results, errors)


def _as_bytes(source) -> tuple[bytes, str]:
    if isinstance(source, (bytes, bytearray)):
        return bytes(source), "<bytes>"
    if isinstance(source, Path) or (isinstance(source, str) and "\n" not in source and Path(source).is_file()):
        path = Path(source)
        return path.read_bytes(), str(path)
    return str(source).encode("utf-8"), "<string>"


def lint(source, *, select=None, ignore=None, name=None):
    data, default_name = _as_bytes(source)
    selection = Selection(list(select) if select else None, [], list(ignore or []))
    return lint_bytes(data, name or default_name, selection)


def load(source, *, defaults=None):
    from .model import build_model

    data, name = _as_bytes(source)
    default_data = None
    if defaults is not None:
        default_data = _as_bytes(defaults)
    return build_model(data, name, default_data)

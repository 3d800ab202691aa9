"""The library API the CLI and tests call: lint files and load typed models."""

from __future__ import annotations

import os
from concurrent.futures import ProcessPoolExecutor
from dataclasses import dataclass, field
from pathlib import Path

from .config import ConfigError, Overrides, ResolvedConfig, discover, load_file, matches_glob
from .context import Options
from .linter import FileResult, FileSettings, Selection, check_bytes, lint_bytes, lint_path

# Below this many files, starting worker processes costs more than it saves.
PARALLEL_THRESHOLD = 8


@dataclass
class LintRequest:
    paths: list[str]
    overrides: Overrides = field(default_factory=Overrides)
    config_file: str | None = None
    stdin_filename: str | None = None
    jobs: int | None = None  # None: all cores


@dataclass
class LintOutcome:
    results: list[FileResult]
    errors: list[str]
    fail_on: str = "error"

    @property
    def sources(self) -> dict[str, list[str]]:
        return {r.name: r.source_lines for r in self.results if r.source_lines}


@dataclass(frozen=True)
class Target:
    """One list to lint: a path on disk, or standard input under a display name."""

    name: str
    path: Path | None
    config: ResolvedConfig


def file_settings(config: ResolvedConfig, overrides: Overrides, target: Path) -> FileSettings:
    settings = overrides.apply(config.settings)
    selection = Selection(settings.select, list(settings.extend_select),
                          [*settings.ignore, *config.ignored_for(target)])
    options = Options(settings.unknown_parameters, settings.cycle_time_us, settings.repeatability_tolerance_um)
    return FileSettings(selection, options, dict(settings.severity))


class Linter:
    """Resolves configuration per file and lints targets, serially or on several cores."""

    def __init__(self, request: LintRequest):
        self.request = request
        self.fixed_config = load_file(Path(request.config_file)) if request.config_file else None

    def config_for(self, path: Path) -> ResolvedConfig:
        return self.fixed_config or discover(path)

    def discover(self) -> tuple[list[Target], list[str]]:
        """Expand directories by the include/exclude globs; explicit files are always linted."""
        targets: list[Target] = []
        errors: list[str] = []
        for raw in self.request.paths:
            if raw == "-":
                name = self.request.stdin_filename or "<stdin>"
                config = self.config_for(Path(name) if self.request.stdin_filename else Path.cwd())
                targets.append(Target(name, None, config))
                continue
            path = Path(raw)
            if path.is_dir():
                for found in self._walk(path):
                    targets.append(Target(str(found), found, self.config_for(found)))
            elif path.exists():
                targets.append(Target(raw, path, self.config_for(path)))
            else:
                errors.append(f"{raw}: no such file or directory")
        return targets, errors

    def _walk(self, folder: Path) -> list[Path]:
        found = []
        for root, dirs, files in os.walk(folder):
            dirs[:] = sorted(d for d in dirs if not d.startswith("."))
            for name in sorted(files):
                path = Path(root) / name
                config = self.config_for(path)
                include = self.request.overrides.apply(config.settings).include
                if any(matches_glob(name.lower(), pattern.lower()) for pattern in include) and not config.excluded(path):
                    found.append(path)
        return found

    def settings_for(self, target: Target) -> FileSettings:
        return file_settings(target.config, self.request.overrides, target.path or Path(target.name))

    def run(self, stdin=None, progress=None) -> LintOutcome:
        targets, errors = self.discover()
        jobs = self.request.jobs or os.cpu_count() or 1
        work = [(t.name, str(t.path) if t.path else None, self.settings_for(t)) for t in targets if t.path]
        if jobs > 1 and len(work) >= PARALLEL_THRESHOLD:
            with ProcessPoolExecutor(max_workers=jobs) as pool:
                disk = list(_track(pool.map(_lint_one, work, chunksize=max(1, len(work) // (jobs * 8))), progress, len(work)))
        else:
            disk = list(_track(map(_lint_one, work), progress, len(work)))
        results: list[FileResult] = []
        from_disk = iter(disk)
        for target in targets:
            if target.path is None:
                data = stdin.read() if stdin is not None else b""
                result = check_bytes(data, target.name, self.settings_for(target))
            else:
                result = next(from_disk)
            if result.error:
                errors.append(result.error)
            results.append(result)
        run_config = self.fixed_config or discover(Path.cwd())
        fail_on = self.request.overrides.fail_on or run_config.settings.fail_on
        return LintOutcome(results, errors, fail_on)


def _lint_one(item: tuple[str, str, FileSettings]) -> FileResult:
    name, path, settings = item
    return lint_path(Path(path), name, settings)


def _track(results, progress, total: int):
    """Pass results through, advancing a progress callback if there is one."""
    for result in results:
        if progress is not None:
            progress(total)
        yield result


def run_lint(request: LintRequest, stdin=None, progress=None) -> LintOutcome:
    """Lint what the request names. Raises `ConfigError` for an unusable configuration."""
    return Linter(request).run(stdin, progress)


def _as_bytes(source) -> tuple[bytes, str]:
    if isinstance(source, (bytes, bytearray)):
        return bytes(source), "<bytes>"
    if isinstance(source, Path) or (isinstance(source, str) and "\n" not in source and Path(source).is_file()):
        path = Path(source)
        return path.read_bytes(), str(path)
    return str(source).encode("utf-8"), "<string>"


def lint(source, *, select=None, ignore=None, name=None):
    """Diagnostics for one list (path, bytes or text), with the built-in defaults and no config files."""
    data, default_name = _as_bytes(source)
    settings = FileSettings(Selection(list(select) if select else None, [], list(ignore or [])))
    return lint_bytes(data, name or default_name, settings)


def load(source, *, defaults=None):
    from .model import build_model

    data, name = _as_bytes(source)
    default_data = _as_bytes(defaults) if defaults is not None else None
    return build_model(data, name, default_data)


__all__ = ["ConfigError", "LintRequest", "LintOutcome", "Linter", "run_lint", "lint", "load"]

"""The library API the CLI and tests call: lint files and load typed models."""

from __future__ import annotations

import os
from dataclasses import dataclass, field
from pathlib import Path

from .config import ConfigError, Overrides, ResolvedConfig, discover, load_file, matches_glob
from .context import Options
from .diagnostics import Diagnostic, Severity
from .machine import is_startup_list, read_startup
from .linter import FileResult, FileSettings, Selection, check_bytes, lint_bytes
from .syntax import split_lines

# Below this many files, starting worker processes costs more than it saves.
PARALLEL_THRESHOLD = 8


@dataclass
class LintRequest:
    paths: list[str]
    overrides: Overrides = field(default_factory=Overrides)
    config_file: str | None = None
    stdin_filename: str | None = None
    jobs: int | None = None  # None: all cores
    fix: bool = False
    unsafe_fixes: bool = False
    show_diff: bool = False  # with fix: report the changes instead of writing them
    keep_source: bool = True  # keep line texts for code frames (the full and gitlab formats need them)


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
    machine: str | None = None  # lists with the same key are checked together (LIS5xx)
    defaults: Path | None = None  # default axis list loaded underneath (from a start-up list)


def file_settings(config: ResolvedConfig, overrides: Overrides, target: Path, keep_source: bool = True) -> FileSettings:
    settings = overrides.apply(config.settings)
    selection = Selection(settings.select, list(settings.extend_select),
                          [*settings.ignore, *config.ignored_for(target)])
    options = Options(settings.unknown_parameters, settings.cycle_time_us, settings.repeatability_tolerance_um)
    return FileSettings(selection, options, dict(settings.severity), keep_source)


class Linter:
    """Resolves configuration per file and lints targets, serially or on several cores."""

    def __init__(self, request: LintRequest):
        self.request = request
        self.startups = []
        self.fixed_config = load_file(Path(request.config_file)) if request.config_file else None

    def config_for(self, path: Path) -> ResolvedConfig:
        return self.fixed_config or discover(path)

    def discover(self) -> tuple[list[Target], list[str]]:
        """Expand directories by the include/exclude globs and start-up lists by their entries;
        explicit files are always linted."""
        targets: list[Target] = []
        errors: list[str] = []
        self.startups = []
        for raw in self.request.paths:
            if raw == "-":
                name = self.request.stdin_filename or "<stdin>"
                config = self.config_for(Path(name) if self.request.stdin_filename else Path.cwd())
                targets.append(Target(name, None, config))
                continue
            path = Path(raw)
            if path.is_dir():
                for found in self._walk(path):
                    targets.append(Target(str(found), found, self.config_for(found), machine=str(found.parent)))
            elif path.exists() and is_startup_list(path):
                targets.extend(self._startup_targets(path))
            elif path.exists():
                targets.append(Target(raw, path, self.config_for(path), machine=str(path.parent)))
            else:
                errors.append(f"{raw}: no such file or directory")
        return targets, errors

    def _startup_targets(self, path: Path) -> list[Target]:
        startup = read_startup(path)
        self.startups.append(startup)
        defaults = startup.default.path if startup.default else None
        return [Target(str(entry.path), entry.path, self.config_for(entry.path), machine=str(path), defaults=defaults)
                for entry in startup.axes if entry.path is not None]

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

    def _machine_level(self, targets: list[Target], results: list[FileResult]) -> list[FileResult]:
        """Run the machine-level rules per machine; returns results for start-up lists with findings."""
        from .rules import registry

        by_name = {result.name: result for result in results}
        groups: dict[str, list[tuple[str, dict]]] = {}
        settings = {}
        for target, result in zip(targets, results):
            if target.machine and result.summary is not None and not result.error:
                groups.setdefault(target.machine, []).append((result.name, result.summary))
                settings[result.name] = self.settings_for(target)
        extra: dict[str, FileResult] = {}
        for key, members in groups.items():
            startups = [s for s in self.startups if str(s.path) == key]
            for code, rule in registry().items():
                if rule.check_machine is None:
                    continue
                for d in rule.check_machine(members, startups):
                    owner = by_name.get(d.path)
                    chosen = settings.get(d.path) or self.settings_for(Target(d.path, Path(d.path), self.config_for(Path(d.path))))
                    if not chosen.selection.enabled(code):
                        continue
                    override = chosen.severity.get(code)
                    if override:
                        d.severity = Severity(override)
                    if owner is None:
                        owner = extra.setdefault(d.path, FileResult(d.path, []))
                    owner.diagnostics.append(d)
                    owner.diagnostics.sort(key=Diagnostic.sort_key)
        for startup in self.startups:  # start-up lists without axis lists still get LIS504
            if str(startup.path) not in groups:
                for d in registry()["LIS504"].check_machine([], [startup]):
                    extra.setdefault(d.path, FileResult(d.path, [])).diagnostics.append(d)
        for result in list(by_name.values()) + list(extra.values()):
            if self.request.keep_source and result.diagnostics and not result.source_lines and result.name != "<stdin>":
                try:
                    result.source_lines = split_lines(Path(result.name).read_bytes().decode("latin-1"))
                except OSError:
                    pass
        return list(extra.values())

    def settings_for(self, target: Target) -> FileSettings:
        return file_settings(target.config, self.request.overrides, target.path or Path(target.name),
                             self.request.keep_source)

    def run(self, stdin=None, progress=None) -> LintOutcome:
        targets, errors = self.discover()
        jobs = self.request.jobs or os.cpu_count() or 1
        mode = (self.request.fix, self.request.unsafe_fixes, self.request.show_diff)
        work = [(t.name, str(t.path), self.settings_for(t), mode, str(t.defaults) if t.defaults else None)
                for t in targets if t.path]
        if jobs > 1 and len(work) >= PARALLEL_THRESHOLD:
            from concurrent.futures import ProcessPoolExecutor  # only paid for when parallel

            with ProcessPoolExecutor(max_workers=jobs) as pool:
                disk = list(_track(pool.map(_lint_one, work, chunksize=max(1, len(work) // (jobs * 8))), progress, len(work)))
        else:
            disk = list(_track(map(_lint_one, work), progress, len(work)))
        results: list[FileResult] = []
        from_disk = iter(disk)
        for target in targets:
            if target.path is None:
                data = stdin.read() if stdin is not None else b""
                result = _process(data, target.name, self.settings_for(target), mode, None, None)
            else:
                result = next(from_disk)
            if result.error:
                errors.append(result.error)
            results.append(result)
        results.extend(self._machine_level(targets, results))
        run_config = self.fixed_config or discover(Path.cwd())
        fail_on = self.request.overrides.fail_on or run_config.settings.fail_on
        return LintOutcome(results, errors, fail_on)


def _lint_one(item) -> FileResult:
    name, path, settings, mode, defaults = item
    try:
        data = Path(path).read_bytes()
        default_data = Path(defaults).read_bytes() if defaults else None
    except OSError as exc:
        return FileResult(name, [], f"cannot read {exc.filename or name}: {exc.strerror or exc}")
    return _process(data, name, settings, mode, Path(path), default_data)


def _process(data: bytes, name: str, settings: FileSettings, mode, path: Path | None,
             defaults: bytes | None) -> FileResult:
    """Lint one list; with --fix, fix it first (writing the file, or describing the change with --diff)."""
    fix, unsafe, show_diff = mode
    if not fix:
        return check_bytes(data, name, settings, defaults)
    from .fixer import fix_bytes
    from .fmt import ChangedOnDisk, unified_diff, write_atomically

    outcome = fix_bytes(data, name, settings, unsafe=unsafe)
    result = outcome.result
    result.fixed = outcome.fixed
    if outcome.data != data:
        if show_diff:
            result.diff = unified_diff(data, outcome.data, name, "fixed")
        elif path is None:
            result.fixed_data = outcome.data
        else:
            try:
                write_atomically(path, outcome.data, expected=data)
            except ChangedOnDisk as exc:
                result.error = str(exc)
            except OSError as exc:
                result.error = f"cannot write {name}: {exc.strerror or exc}"
    elif path is None and not show_diff:
        result.fixed_data = data
    return result


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

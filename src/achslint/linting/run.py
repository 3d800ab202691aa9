"""A lint run: the lists a `Finder` finds, each linted (and fixed) on one or several cores, the machine
step, and the homing programs checked against their machines; what `achslint lint` and `run_lint` do."""

from __future__ import annotations

import contextlib
import os
from collections.abc import Callable, Iterable, Iterator, Sequence
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import TYPE_CHECKING, Any, BinaryIO

from ..axis.source import read_one_list
from ..core.decode import UnreadableInput
from ..core.display import shortened
from ..core.files import (
    MISSING,
    ChangedOnDisk,
    Refused,
    WriteFailed,
    is_xml,
    not_a_list_file,
    read_list,
    reason,
    same_file,
    shown_path,
    write_atomically,
)
from ..rules import Scope as RuleScope
from .config import (
    PROGRAM_SUFFIXES,
    Overrides,
    ResolvedConfig,
    Settings,
    discover,
    named_path,
)
from .discovery import Discovery, Finder, Target, machine_files, startup_files
from .engine import enabled_checks
from .linter import (
    FileResult,
    FileSettings,
    file_settings,
    lint_file,
)
from .machines import machine_findings

if TYPE_CHECKING:
    pass

# A list given to the library functions: a path (str or PathLike) or the list's bytes.


# What --fix asks for: (fix, unsafe fixes too, show the diff instead of writing, add noqa instead of fixing).
FixMode = tuple[bool, bool, bool, bool]
# One list for a worker process: (name, path, settings, fix mode, default list path).
WorkItem = tuple[str, str, FileSettings, FixMode, "str | None"]
# Called with the total number of lists after each list is done.
Progress = Callable[[int], None]

# Below this many files, starting worker processes costs more than it saves; and unless --jobs asks for
# processes, also below this much text: on two cores 148 small lists (100 KB) took 0.47 s serially and
# 0.51 s on two processes, ten lists of 306 KB 255 ms serially and 238 ms on two (2026-11-21).
PARALLEL_THRESHOLD = 8
PARALLEL_MIN_BYTES = 256 * 1024


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
    force_exclude: bool = False  # exclude patterns apply to named files too
    respect_gitignore: bool = True  # files git ignores are not searched in folders
    machine: str | None = None  # start-up list of the machine NC programs (`rfp.nc`) are checked against
    channel: int = 1  # the channel whose axis names the programs use
    output: str | None = None  # the report file (-o): a run that would read it as an input stops first
    follow_startup: bool = False  # --fix may rewrite the lists a named start-up list reaches in other folders
    add_noqa: bool = False  # write a `noqa` for every finding instead of reporting it (`linting.noqa`)


class OutputIsInput(ValueError):
    """The report file (`-o/--output-file`) is one of the files the run reads: writing it would replace
    that file with the report. A usage error, raised before anything is read or written."""


@dataclass
class LintOutcome:
    results: list[FileResult]
    errors: list[str]
    notes: list[str] = field(default_factory=list)  # files skipped on purpose (FIFOs, links leading outside)
    skipped: int = 0  # lists found and skipped on purpose (another kind of list, XML without an axis list)
    excluded: list[str] = field(default_factory=list)  # named paths --force-exclude left out

    @property
    def failing(self) -> bool:
        """Whether some file has a finding at or above the fail-on of the configuration nearest to it."""
        return any(result.failing for result in self.results)

    @property
    def sources(self) -> dict[str, list[str]]:
        return {r.name: r.source_lines for r in self.results if r.source_lines}


class LintRun:
    """Resolves configuration per file and lints the lists a `Finder` finds, serially or on several cores."""

    def __init__(self, request: LintRequest) -> None:
        self.request = request
        self.finder = Finder(
            request.overrides,
            request.config_file,
            request.stdin_filename,
            request.force_exclude,
            request.respect_gitignore,
            request.follow_startup,
            machine_rules=self._machine_rules,
        )
        self.found = Discovery()

    def config_for(self, path: Path) -> ResolvedConfig:
        return self.finder.config_for(path)

    def settings_for(self, target: Target) -> FileSettings:
        settings = file_settings(
            target.config, self.request.overrides, target.path or Path(target.name), self.request.keep_source
        )
        settings.kind = target.kind
        return settings

    def _machine_rules(self, path: Path) -> bool:
        """Whether a machine-level rule runs for a named list (only then are its neighbours read)."""
        settings = self.settings_for(Target(str(path), path, self.config_for(path)))
        return bool(enabled_checks(RuleScope.MACHINE, settings.policy))

    def run(self, stdin: BinaryIO | None = None, progress: Progress | None = None) -> LintOutcome:
        found = self.found = self.finder.find(self.request.paths)
        if self.request.output is not None:
            every = [*found.targets, *found.context]
            read = [t.path for t in every if t.path is not None]
            read += [t.defaults for t in every if t.defaults is not None]
            read += [t.config.path for t in every if t.config.path is not None]
            read += [path for startup in found.startups for path in startup_files(startup)]
            refuse_output_over_input(self.request.output, read)
        targets, errors = found.targets, found.errors
        # standard input the editor names as an excluded file (--force-exclude): left out on purpose, as ruff
        # does, never "no list found"; named files all excluded still make an empty run (exit 2)
        skipped = found.excluded.count("-")
        jobs = self.request.jobs or os.cpu_count() or 1
        mode = (self.request.fix, self.request.unsafe_fixes, self.request.show_diff, self.request.add_noqa)
        kept = (False, False, False, False)  # lists the user did not name: checked, never rewritten
        work = [
            (
                t.name,
                str(t.path),
                self.settings_for(t),
                mode if t.writable else kept,
                str(t.defaults or "") or None,
            )
            for t in targets
            if t.path
        ]
        if (self.request.fix and not self.request.show_diff) or self.request.add_noqa:
            found.notes += not_rewritten([t for t in targets if not t.writable])
        if jobs > 1 and len(work) >= PARALLEL_THRESHOLD and (self.request.jobs or _enough_text(work)):
            from concurrent.futures import ProcessPoolExecutor  # only paid for when parallel

            from ..core.signals import install

            pool = ProcessPoolExecutor(max_workers=jobs, initializer=install)
            try:
                disk = list(
                    _track(
                        pool.map(_lint_one, work, chunksize=max(1, len(work) // (jobs * 8))),
                        progress,
                        len(work),
                    )
                )
            finally:
                # On an interrupt, drop the work not started yet instead of finishing it.
                pool.shutdown(cancel_futures=True)
        else:
            disk = list(_track(map(_lint_one, work), progress, len(work)))
        pairs: list[tuple[Target, FileResult]] = []
        if "-" in found.excluded and self.request.fix and not self.request.show_diff:
            # `--fix -` prints the fixed list: an excluded one comes back as it went in (an editor that
            # pipes its buffer through achslint must not get an empty one back)
            name = self.request.stdin_filename or "<stdin>"
            pairs.append((Target(name, None, ResolvedConfig(Settings())), _unchanged(name, stdin)))
        from_disk = iter(disk)
        for target in targets:
            if target.path is None:
                data = stdin.read() if stdin is not None else b""
                result = _process(data, target.name, self.settings_for(target), mode, None, None)
            else:
                result = next(from_disk)
            if result.note:  # skipped on purpose (a list of another kind, XML without an axis list)
                found.notes.append(result.note)
                skipped += 1
                continue
            if result.error:
                errors.append(result.error)
            result.fail_on = self.settings_for(target).fail_on
            pairs.append((target, result))
        context = self._context(found.context)
        hidden = {result.name for _, result in context}
        hidden |= {str(s.path) for s in found.startups if str(s.path) not in found.reported}
        results = [result for _, result in pairs]
        results.extend(
            machine_findings(
                [*context, *pairs],
                found.startups,
                self.settings_for,
                self.config_for,
                hidden=hidden,
                keep_source=self.request.keep_source,
            )
        )
        excluded = [path for path in found.excluded if path != "-"]
        return LintOutcome(results, errors, found.notes, skipped, excluded)

    def _context(self, context: list[Target]) -> list[tuple[Target, FileResult]]:
        """Lint the neighbours of named lists for their machine summaries only (never fixed, never shown)."""
        pairs = []
        for target in context:
            chosen = self.settings_for(target)
            only_machine = replace(chosen.settings, select=["LIS5"], extend_select=[])
            settings = replace(chosen, settings=only_machine, keep_source=False)
            defaults = str(target.defaults) if target.defaults else None
            result = _lint_one(
                (target.name, str(target.path), settings, (False, False, False, False), defaults)
            )
            if not result.error and not result.note:
                pairs.append((target, result))
        return pairs


def _unchanged(name: str, stdin: BinaryIO | None) -> FileResult:
    """The result for standard input left out by --force-exclude under --fix: its text, unchanged."""
    return FileResult(name, [], fixed_data=stdin.read() if stdin is not None else b"")


def _lint_one(item: WorkItem) -> FileResult:
    name, path, settings, mode, defaults = item
    try:
        data = read_list(Path(path))
        default_data = read_one_list(Path(defaults), defaults) if defaults else None
    except OSError as exc:
        return FileResult(
            name,
            [],
            str(exc) if isinstance(exc, Refused) else f"cannot read {exc.filename or name}: {reason(exc)}",
        )
    except UnreadableInput as exc:  # the list underneath (a default list, the list an update changes)
        said = str(exc).removeprefix(f"{defaults}: ")
        return FileResult(name, [], f"{name}: the list loaded under it, {defaults}, cannot be read: {said}")
    return _process(data, name, settings, mode, Path(path), default_data)


def _process(
    data: bytes,
    name: str,
    settings: FileSettings,
    mode: FixMode,
    path: Path | None,
    defaults: bytes | None,
) -> FileResult:
    """Lint one list; with --fix, fix it first (writing the file, or describing the change with --diff); with
    --add-noqa, suppress its findings in the file."""
    fix, unsafe, show_diff, noqa = mode
    if noqa:
        return _add_noqa(data, name, settings, path, defaults)
    if not fix:
        linted = lint_file(data, name, settings, defaults)
        if not linted.error and any(
            d.fix is not None and d.fix.applicability == "safe" for d in linted.diagnostics
        ):
            from .fixer import check_fixes

            check_fixes(data, name, settings, linted, defaults)  # a fix --fix would refuse is not called safe
        return linted
    from ..syntax.diff import unified_diff
    from .fixer import fix_bytes

    outcome = fix_bytes(data, name, settings, unsafe=unsafe, defaults=defaults)
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
            except OSError as exc:
                result.error = write_error(exc, name)
                result.fixed = 0  # nothing was written, so nothing was fixed
    elif path is None and not show_diff:
        result.fixed_data = data
    return result


def _add_noqa(
    data: bytes, name: str, settings: FileSettings, path: Path | None, defaults: bytes | None
) -> FileResult:
    """`--add-noqa` on one list on disk: a `noqa` for each finding, written atomically; the result holds
    what is left (findings no `noqa` in the list can suppress). XML files are never rewritten."""
    from .noqa import add_noqa

    result = lint_file(data, name, settings, defaults)
    if result.error or result.note or path is None or is_xml(name):
        return result
    new_data, added = add_noqa(data, result.diagnostics, name)
    if not added:
        return result
    try:
        write_atomically(path, new_data, expected=data)
    except OSError as exc:
        result.error = write_error(exc, name)
        return result
    result = lint_file(new_data, name, settings, defaults)
    result.noqa_added = added
    return result


@dataclass(frozen=True)
class ListedFile:
    """A file a run would lint (`lint --show-files`): its name, its kind and the machines it belongs to."""

    name: str
    kind: str  # a catalogue kind id (axis, channel, startup ...), "xml", or why it cannot be told
    machines: tuple[str, ...]


def files_to_lint(request: LintRequest) -> list[ListedFile]:
    """What `request` would lint, in the order it would: the lists its paths come to (named, found in
    folders, named by start-up lists) and the NC programs among them; the lists read only for the machine
    rules are not linted, so not listed."""
    from ..syntax.parser import parse_bytes
    from .linter import list_kind

    rest = [path for path in request.paths if not is_program(path)]
    found = LintRun(replace(request, paths=rest)).finder.find(rest) if rest else Discovery()
    listed: list[ListedFile] = []
    for target in found.targets:
        if target.path is None:
            listed.append(ListedFile(target.name, "standard input", ()))
            continue
        if is_xml(target.name):
            kind = "xml"
        else:
            try:
                file = parse_bytes(read_list(target.path), target.name)
                kind = list_kind(file, target.name, target.kind).id
            except (OSError, UnreadableInput) as exc:
                kind = f"unreadable ({reason(exc) if isinstance(exc, OSError) else exc})"
        listed.append(ListedFile(target.name, kind, target.machines))
    listed += [ListedFile(path, "program", ()) for path in request.paths if is_program(path)]
    return listed


def settings_for(request: LintRequest) -> tuple[ResolvedConfig, Settings]:
    """The configuration for the first path of `request` (`--config`, or the nearest one) and the settings
    a run uses for it: the file's, with the command line's overrides applied (`lint --show-settings`)."""
    first = request.paths[0] if request.paths else "."
    if first == "-":
        first = request.stdin_filename or str(Path.cwd())
    config = LintRun(request).config_for(Path(first))
    return config, request.overrides.apply(config.settings)


def write_error(exc: OSError, name: str) -> str:
    """The one-line message for a write that did not happen."""
    if isinstance(exc, (ChangedOnDisk, Refused, WriteFailed)):
        return str(exc)
    return f"cannot write {name}: {reason(exc)}"


def _enough_text(work: Sequence[tuple[Any, ...]]) -> bool:
    """Whether the files of `work` (path second) hold enough text to share out between processes."""
    total = 0
    for item in work:
        with contextlib.suppress(OSError, ValueError):  # the lint itself reports an unreadable file
            total += os.stat(item[1]).st_size
        if total >= PARALLEL_MIN_BYTES:
            return True
    return False


def _track(results: Iterable[FileResult], progress: Progress | None, total: int) -> Iterator[FileResult]:
    """Pass results through, advancing a progress callback if there is one."""
    for result in results:
        if progress is not None:
            progress(total)
        yield result


def run_lint(
    request: LintRequest, stdin: BinaryIO | None = None, progress: Progress | None = None
) -> LintOutcome:
    """Lint what the request names. Raises `ConfigError` for an unusable configuration.

    NC programs (`rfp.nc`) among the paths are checked against the machine of `request.machine` (LIS6xx).
    """
    if request.output is not None:
        named = [*request.paths, *(p for p in (request.machine, request.config_file) if p is not None)]
        read = [Path(p) for p in named if p != "-"]
        if request.machine is not None and any(is_program(path) for path in request.paths):
            root = Path(request.overrides.cnc_root) if request.overrides.cnc_root else None
            read += machine_files(Path(request.machine), root, request.config_file)
        if request.config_file is None:  # the report's settings (docs-url) come from the working directory's
            read += [path for path in [discover(Path.cwd()).path] if path is not None]
        refuse_output_over_input(request.output, read)
    programs = [path for path in request.paths if is_program(path)]
    rest = [path for path in request.paths if not is_program(path)]
    run = LintRun(replace(request, paths=rest))
    outcome = run.run(stdin, progress) if rest or not programs else LintOutcome([], [])
    if programs:
        from .program import lint_programs

        results, errors = lint_programs(
            programs,
            Path(request.machine) if request.machine is not None else None,
            lambda path: run.settings_for(Target(str(path), path, run.config_for(path))),
            cnc_root=Path(request.overrides.cnc_root) if request.overrides.cnc_root else None,
            channel=request.channel,
        )
        outcome.results.extend(results)
        outcome.errors.extend(errors)
    _configured_programs(run, {os.path.realpath(path) for path in programs}, outcome)
    return outcome


def refuse_output_over_input(output: str, inputs: Iterable[Path], option: str = "--output-file") -> None:
    """`OutputIsInput` when the file `option` writes is one of `inputs` (the same file under another name,
    through a symbolic or a hard link, counts: it is compared by device and inode)."""
    for path in inputs:
        if same_file(Path(output), path):
            raise OutputIsInput(
                f"{option} {output} is {path}, which this run reads; writing it would replace that file: "
                "give another file name"
            )


def is_program(path: str) -> bool:
    """Whether a path names an NC program (`rfp.nc`) rather than a list."""
    return path.lower().endswith(PROGRAM_SUFFIXES)


def _configured_programs(run: LintRun, done: set[str], outcome: LintOutcome) -> None:
    """The homing programs the configuration of each linted start-up list names (`homing-programs`),
    checked against that start-up list's machine."""
    given_root = Path(run.request.overrides.cnc_root) if run.request.overrides.cnc_root else None
    found = run.found
    startups = {
        os.path.realpath(s.path): (s.path, s.root) for s in found.startups if str(s.path) in found.reported
    }
    for path in found.program_startups:  # found in the linted folders
        startups.setdefault(os.path.realpath(path), (path, given_root))
    for startup, cnc_root in startups.values():
        config = run.config_for(startup)
        wanted = (
            [named_path(config.path, name) for name in config.settings.homing_programs] if config.path else []
        )
        todo = [path for path in wanted if os.path.realpath(path) not in done]
        if not todo:
            continue
        if run.request.output is not None:
            refuse_output_over_input(run.request.output, todo)
        from ..machine.build import MachineError, build_machine  # only for machines with programs
        from .program import lint_program_bytes

        try:
            machine = build_machine(startup, cnc_root=cnc_root)
        except MachineError as exc:
            outcome.errors.append(f"{config.path}: homing-programs: {exc}")
            continue
        for path in todo:
            done.add(os.path.realpath(path))
            missing = not_a_list_file(path)
            if missing in MISSING:
                outcome.errors.append(
                    f"{config.path}: homing-programs names {shortened(path.name)}: {missing}"
                )
                continue
            data, problem = _configured_program(path)
            if data is None:
                outcome.errors.append(
                    f"configuration error in {config.path}: key `homing-programs`: {problem}"
                )
                continue
            settings = run.settings_for(Target(str(path), path, run.config_for(path)))
            result = lint_program_bytes(data, machine, shown_path(path), settings)
            outcome.results.append(result)


def _configured_program(path: Path) -> tuple[bytes | None, str]:
    """(the bytes, "") of a file a configuration names as a homing program, read once; (None, why) when it
    is none (not a regular file, too large, binary or UTF-16). Its lines are never shown."""
    from ..core.files import read_program_file
    from ..machine.program import program_text

    try:
        data = read_program_file(path)
    except Refused as exc:
        return None, str(exc)
    except OSError as exc:
        return None, f"cannot read {shown_path(path)}: {reason(exc)}"
    if program_text(data) is None:
        return (
            None,
            f"{shown_path(path)} is not an NC program (it is not text: binary, or UTF-16); not checked",
        )
    return data, ""


def not_rewritten(targets: list[Target]) -> list[str]:
    """The note for lists a named start-up list reached in folders nobody named: checked, not rewritten."""
    if not targets:
        return []
    names = ", ".join(t.name for t in targets[:3]) + (
        f" and {len(targets) - 3} more" if len(targets) > 3 else ""
    )
    return [
        f"{names}: reached through a start-up list, checked but not rewritten; name them (or their folder) "
        "or pass --follow-startup to rewrite them too"
    ]

"""The library API the CLI and tests call: lint files and load typed models."""

from __future__ import annotations

import contextlib
import os
from collections.abc import Callable, Iterable, Iterator, Sequence
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import TYPE_CHECKING, Any, BinaryIO

from .core.decode import UnreadableInput, decode, text_bytes
from .core.diagnostics import Diagnostic, Severity
from .core.display import shortened
from .core.files import (
    MISSING,
    ChangedOnDisk,
    Refused,
    Scope,
    WriteFailed,
    is_folder,
    is_xml,
    not_a_list_file,
    read_list,
    real_path,
    reason,
    same_file,
    write_atomically,
)
from .linting.config import (
    PROGRAM_SUFFIXES,
    ConfigError,
    Overrides,
    ResolvedConfig,
    discover,
    load_file,
    matches_glob,
    named_path,
)
from .linting.engine import Policy, enabled_checks, run
from .linting.linter import (
    NOT_A_LIST,
    FileResult,
    FileSettings,
    findings,
    lint_file,
    looks_like_a_list,
)
from .machine.startup import is_default_list, is_startup_list, machines, read_startup
from .rules import Scope as RuleScope
from .syntax.parser import parse_bytes, split_lines

if TYPE_CHECKING:
    from .dryrun import DryRun
    from .explanation import ListReport
    from .machine.startup import Member, Startup
    from .model.base import AxisBase

# A list given to the library functions: a path (str or PathLike) or the list's bytes.
Source = str | os.PathLike[str] | bytes
# What --fix asks for: (fix, unsafe fixes too, show the diff instead of writing).
FixMode = tuple[bool, bool, bool]
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


class OutputIsInput(ValueError):
    """The report file (`-o/--output-file`) is one of the files the run reads: writing it would replace
    that file with the report. A usage error, raised before anything is read or written."""


@dataclass
class LintOutcome:
    results: list[FileResult]
    errors: list[str]
    notes: list[str] = field(default_factory=list)  # files skipped on purpose (FIFOs, links leading outside)

    @property
    def failing(self) -> bool:
        """Whether some file has a finding at or above the fail-on of the configuration nearest to it."""
        return any(result.failing for result in self.results)

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


def file_settings(
    config: ResolvedConfig, overrides: Overrides, target: Path, keep_source: bool = True
) -> FileSettings:
    return FileSettings(
        overrides.apply(config.settings),
        config.ignored_for(target),
        keep_source=keep_source,
        machine_in_file=False,
    )


@dataclass
class Discovery:
    """What the paths given on the command line come to."""

    targets: list[Target] = field(default_factory=list)
    errors: list[str] = field(default_factory=list)  # exit code 2: something named or found could not be read
    notes: list[str] = field(default_factory=list)  # skipped on purpose; the run goes on
    # Lists of the same machine as a named list, read from disk only for the machine-level rules
    # (LIS501-LIS503): pre-commit passes the changed lists alone, their neighbours still count.
    context: list[Target] = field(default_factory=list)
    _seen: set[object] = field(default_factory=set)

    def add(self, target: Target) -> None:
        """Take a target unless the same file is already taken (named twice, or a folder and a file in it)."""
        if target.path is not None:
            key: object
            try:
                info = os.stat(target.path)
                key = (info.st_dev, info.st_ino)
            except OSError:
                key = str(target.path)
            if key in self._seen:
                return
            self._seen.add(key)
        self.targets.append(target)


class LintRun:
    """Resolves configuration per file and lints targets, serially or on several cores."""

    def __init__(self, request: LintRequest) -> None:
        self.request = request
        self.startups: list[Startup] = []
        # start-up lists found in linted folders whose configuration names homing programs
        self.program_startups: list[Path] = []
        self.fixed_config = load_file(Path(request.config_file)) if request.config_file else None

    def config_for(self, path: Path) -> ResolvedConfig:
        return self.fixed_config or discover(path)

    def discover(self) -> Discovery:
        """Expand folders by the include/exclude globs and start-up lists by their entries; named files are
        always linted. Each file is taken once, however often it is reached."""
        found = Discovery()
        self.startups = []
        self.program_startups = []
        named: dict[str, Path] = {}  # folders of the lists named one by one
        scope = Scope.of(self.request.paths)
        for raw in self.request.paths:
            if raw == "-":
                name = self.request.stdin_filename or "<stdin>"
                config = self.config_for(Path(name) if self.request.stdin_filename else Path.cwd())
                found.add(Target(name, None, config))
                continue
            path = Path(raw)
            if is_folder(path):
                for file in self._walk(path, scope, found):
                    found.add(Target(str(file), file, self.config_for(file), machine=str(file.parent)))
                continue
            problem = not_a_list_file(path)
            if problem is None and self.request.force_exclude and self._excluded(self.config_for(path), path):
                continue
            if problem is not None:
                found.errors.append(f"{raw}: {problem}")
            elif is_startup_list(path):
                self._startup_targets(path, scope, found)
            else:
                found.add(Target(raw, path, self.config_for(path), machine=str(path.parent)))
                named.setdefault(str(path.parent), path.parent)
        for key, folder in named.items():
            self._siblings(key, folder, found)
        return found

    def _siblings(self, key: str, folder: Path, found: Discovery) -> None:
        """The other lists in the folder of a named list, as context for the machine-level rules.

        Only when a machine-level rule is selected; links that lead out of the folder are not followed,
        and nothing about these files is reported (their own problems belong to their own run).
        """
        settings = self.settings_for(Target(key, folder / "x", self.config_for(folder / "x")))
        if not enabled_checks(RuleScope.MACHINE, settings.policy):
            return
        quiet = Discovery()
        for file in self._walk(folder, Scope.of([folder]), quiet, recursive=False):
            before = len(found.targets)
            found.add(Target(str(file), file, self.config_for(file), machine=key))
            if len(found.targets) > before:
                found.context.append(found.targets.pop())

    def _startup_targets(self, path: Path, scope: Scope, found: Discovery) -> None:
        config = self.config_for(path)
        root: Path | None
        if self.request.overrides.cnc_root is not None:
            root, origin = Path(self.request.overrides.cnc_root), "given by --cnc-root"
        else:
            root, origin = config.cnc_root(), f"set by `cnc-root` in {config.path}"
        try:
            startup = read_startup(path, scope, root, origin)
        except OSError as exc:
            found.errors.append(f"cannot read {path}: {reason(exc)}")
            return
        except UnreadableInput as exc:
            found.errors.append(f"{path}: {exc}")
            return
        self.startups.append(startup)
        # An entry naming the start-up list itself is LIS504's; its lines are no axis list (or defaults).
        named = [e for e in [startup.default, *startup.axes] if e and e.path and not same_file(e.path, path)]
        defaults = startup.default.path if startup.default in named and startup.default else None
        for entry in startup.axes:
            if entry in named and entry.path is not None:
                found.add(
                    Target(
                        _shown(entry.path),
                        entry.path,
                        self.config_for(entry.path),
                        machine=str(path),
                        defaults=defaults,
                    )
                )

    def _walk(self, folder: Path, scope: Scope, found: Discovery, recursive: bool = True) -> list[Path]:
        """The lists in a folder tree. A folder that cannot be read, or a list that cannot (a broken link, a
        loop), is an error: those could be lists nobody checked. FIFOs, devices and links that lead
        outside the paths given are skipped with a note: they are not lists of this project."""
        lists = []

        def unreadable(exc: OSError) -> None:
            found.errors.append(f"cannot read folder {exc.filename}: {reason(exc)}")

        for root, dirs, files in os.walk(folder, onerror=unreadable):
            dirs[:] = sorted(d for d in dirs if not d.startswith(".")) if recursive else []
            for name in dirs:  # os.walk does not enter linked folders; one that leads outside is said
                linked = Path(root) / name
                if os.path.islink(linked) and not scope.contains(linked):
                    found.notes.append(
                        f"{linked}: skipped, it links to {real_path(linked)}, outside the paths given"
                    )
            config = self.config_for(Path(root) / "x")
            include = self.request.overrides.apply(config.settings).include
            for name in sorted(files):
                path = Path(root) / name
                if config.settings.homing_programs and is_startup_list(path):
                    self.program_startups.append(path)  # its homing programs are checked too
                xml = is_xml(name)  # axis XML is found by content, whatever the export calls it
                if not xml and not any(matches_glob(name.lower(), pattern.lower()) for pattern in include):
                    continue
                if self._excluded(config, path):
                    continue
                problem = not_a_list_file(path)
                if xml and problem is None and scope.contains(path) and not self._axis_xml(path, found):
                    continue
                if problem is None and not scope.contains(path):
                    found.notes.append(
                        f"{path}: skipped, it links to {real_path(path)}, outside the paths given"
                    )
                elif problem is not None and problem.startswith(SKIPPED_KINDS):
                    found.notes.append(f"{path}: skipped, it is {problem}")
                elif problem is not None:
                    found.errors.append(f"cannot read {path}: {problem}")
                else:
                    lists.append(path)
        return _not_ignored_by_git(folder, lists) if self.request.respect_gitignore else lists

    def _excluded(self, config: ResolvedConfig, path: Path) -> bool:
        patterns = self.request.overrides.apply(config.settings).exclude
        return any(matches_glob(config.relative(path), pattern) for pattern in patterns)

    @staticmethod
    def _axis_xml(path: Path, found: Discovery) -> bool:
        """Whether an XML file found in a folder may hold axis lists; the others get a note."""
        from .syntax.xmlinput import may_hold_axis_list, root_element

        try:
            data = read_list(path)
        except OSError as exc:
            found.errors.append(f"cannot read {path}: {reason(exc)}")
            return False
        if may_hold_axis_list(data):
            return True
        found.notes.append(f"{path}: skipped, an XML file without an axis list (<{root_element(data)}>)")
        return False

    def machine_level(
        self,
        targets: list[Target],
        results: list[FileResult],
        context: Sequence[tuple[Target, FileResult]] = (),
    ) -> list[FileResult]:
        """Run the machine-level rules per machine; returns results for start-up lists with findings.

        `context` lists (the neighbours of named lists) take part but get no findings; they come first,
        so a repeated axis number is reported on the named list that repeats it.
        """
        by_name = {result.name: result for result in results}
        hidden = {result.name for _, result in context}
        groups: dict[str, list[Member]] = {}
        settings: dict[str, FileSettings] = {}
        pairs = [*context, *zip(targets, results, strict=False)]
        for target, result in pairs:
            if target.path is not None and is_default_list(target.path):
                continue  # loaded underneath the axes, not an axis of its own
            if target.machine and not result.error and (result.summary is not None or result.summaries):
                for summary in [result.summary] if result.summary is not None else result.summaries:
                    groups.setdefault(target.machine, []).append((result.name, summary))
                settings[result.name] = self.settings_for(target)

        def settings_of(path: str) -> FileSettings:  # a start-up list's own configuration too
            if path not in settings:
                settings[path] = self.settings_for(Target(path, Path(path), self.config_for(Path(path))))
            return settings[path]

        policies: dict[str, Policy] = {}

        def policy_of(path: str) -> Policy:
            if path not in policies:
                policies[path] = settings_of(path).policy
            return policies[path]

        extra: dict[str, FileResult] = {}
        for machine in machines(groups, self.startups):
            for d in run(RuleScope.MACHINE, machine, policy_of):
                if d.path in hidden:
                    continue
                owner = by_name.get(d.path) or extra.setdefault(
                    d.path, FileResult(d.path, [], fail_on=settings_of(d.path).fail_on)
                )
                owner.diagnostics.append(d)
        for result in [*by_name.values(), *extra.values()]:
            result.diagnostics.sort(key=Diagnostic.sort_key)
            if (
                self.request.keep_source
                and result.diagnostics
                and not result.source_lines
                and result.name != "<stdin>"
            ):
                with contextlib.suppress(OSError, UnreadableInput):
                    result.source_lines = split_lines(decode(read_list(Path(result.name))).text)
        return list(extra.values())

    def settings_for(self, target: Target) -> FileSettings:
        return file_settings(
            target.config, self.request.overrides, target.path or Path(target.name), self.request.keep_source
        )

    def run(self, stdin: BinaryIO | None = None, progress: Progress | None = None) -> LintOutcome:
        found = self.discover()
        if self.request.output is not None:
            every = [*found.targets, *found.context]
            read = [t.path for t in every if t.path is not None]
            read += [t.defaults for t in every if t.defaults is not None]
            read += [t.config.path for t in every if t.config.path is not None]
            read += [path for startup in self.startups for path in startup_files(startup)]
            refuse_output_over_input(self.request.output, read)
        targets, errors = found.targets, found.errors
        jobs = self.request.jobs or os.cpu_count() or 1
        mode = (self.request.fix, self.request.unsafe_fixes, self.request.show_diff)
        work = [
            (t.name, str(t.path), self.settings_for(t), mode, str(t.defaults) if t.defaults else None)
            for t in targets
            if t.path
        ]
        if jobs > 1 and len(work) >= PARALLEL_THRESHOLD and (self.request.jobs or _enough_text(work)):
            from concurrent.futures import ProcessPoolExecutor  # only paid for when parallel

            from .core.signals import install

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
        results: list[FileResult] = []
        linted: list[Target] = []  # the targets of `results`, in the same order
        from_disk = iter(disk)
        for target in targets:
            if target.path is None:
                data = stdin.read() if stdin is not None else b""
                result = _process(data, target.name, self.settings_for(target), mode, None, None)
            else:
                result = next(from_disk)
            if result.note:
                found.notes.append(result.note)
                continue
            if result.error:
                errors.append(result.error)
            result.fail_on = self.settings_for(target).fail_on
            results.append(result)
            linted.append(target)
        results.extend(self.machine_level(linted, results, self._context(found.context)))
        return LintOutcome(results, errors, found.notes)

    def _context(self, context: list[Target]) -> list[tuple[Target, FileResult]]:
        """Lint the neighbours of named lists for their machine summaries only (never fixed, never shown)."""
        pairs = []
        for target in context:
            chosen = self.settings_for(target)
            only_machine = replace(chosen.settings, select=["LIS5"], extend_select=[])
            settings = replace(chosen, settings=only_machine, keep_source=False)
            result = _lint_one((target.name, str(target.path), settings, (False, False, False), None))
            if not result.error and not result.note:
                pairs.append((target, result))
        return pairs


def _not_ignored_by_git(folder: Path, files: list[Path]) -> list[Path]:
    """`files` without those git ignores (.gitignore, .git/info/exclude); all of them outside a git work tree
    or without git."""
    import subprocess

    if not files or not _maybe_in_git_work_tree(folder):
        return files
    try:
        answer = subprocess.run(
            ["git", "-C", str(folder), "check-ignore", "--stdin", "-z"],
            input=b"\0".join(os.fsencode(os.path.abspath(f)) for f in files) + b"\0",
            capture_output=True,
            timeout=60,
            check=False,
        )
    except (OSError, subprocess.SubprocessError):
        return files
    if answer.returncode != 0:  # 1: nothing ignored; 128: not a git work tree
        return files
    ignored = {os.fsdecode(name) for name in answer.stdout.split(b"\0") if name}
    return [f for f in files if os.path.abspath(f) not in ignored]


def _maybe_in_git_work_tree(folder: Path) -> bool:
    """Whether git could have a say: a `.git` folder or file in the folder or above it, or git pointed
    elsewhere by GIT_DIR / GIT_WORK_TREE. Saves starting git for every folder outside a repository."""
    if os.environ.get("GIT_DIR") or os.environ.get("GIT_WORK_TREE"):
        return True
    try:
        start = Path(os.path.abspath(folder))
        return any(os.path.lexists(candidate / ".git") for candidate in (start, *start.parents))
    except (OSError, ValueError):
        return True  # let git decide


def _shown(path: Path) -> str:
    """A path as reports show it: relative to the working directory when it lies below it."""
    try:
        return str(path.relative_to(Path.cwd()))
    except ValueError:
        return str(path)


# Files found in a folder that are skipped with a note rather than reported as unreadable.
SKIPPED_KINDS = (
    "a FIFO",
    "a device",
    "a socket",
    "a folder",
    "not a regular file",
    "a file of the operating system",
)


def _lint_one(item: WorkItem) -> FileResult:
    name, path, settings, mode, defaults = item
    try:
        data = read_list(Path(path))
        default_data = read_list(Path(defaults)) if defaults else None
    except OSError as exc:
        return FileResult(
            name,
            [],
            str(exc) if isinstance(exc, Refused) else f"cannot read {exc.filename or name}: {reason(exc)}",
        )
    return _process(data, name, settings, mode, Path(path), default_data)


def _process(
    data: bytes,
    name: str,
    settings: FileSettings,
    mode: FixMode,
    path: Path | None,
    defaults: bytes | None,
) -> FileResult:
    """Lint one list; with --fix, fix it first (writing the file, or describing the change with --diff)."""
    fix, unsafe, show_diff = mode
    if not fix:
        return lint_file(data, name, settings, defaults)
    from .fmt import unified_diff
    from .linting.fixer import fix_bytes

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
            except OSError as exc:
                result.error = write_error(exc, name)
                result.fixed = 0  # nothing was written, so nothing was fixed
    elif path is None and not show_diff:
        result.fixed_data = data
    return result


def write_error(exc: OSError, name: str) -> str:
    """The one-line message for a write that did not happen."""
    if isinstance(exc, (ChangedOnDisk, Refused, WriteFailed)):
        return str(exc)
    return f"cannot write {name}: {reason(exc)}"


def read_one_list(path: Path, name: str) -> bytes:
    """The one axis list a file holds, for the commands that read a single list (explain, dry-run, diff).

    The same checks as for lint: a regular file only (never a FIFO or /proc), XML through the one XML
    parser (DTDs and entities refused; the file's only `<AchsMds>` / `<AX_MDS>` list), and a file that is
    not an axis list refused without showing it. Raises `OSError` or `UnreadableInput` with a message.
    """
    problem = not_a_list_file(path)
    if problem is not None:
        raise Refused(f"{name}: {problem}")
    data = read_list(path)
    if is_xml(name):
        from .syntax.xmlinput import single_list

        return single_list(data, name)
    if not looks_like_a_list(parse_bytes(data, name)):
        raise UnreadableInput(f"{name}: {NOT_A_LIST}")
    return data


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
        from .linting.program import lint_programs

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


def startup_files(startup: Startup) -> list[Path]:
    """Every file a start-up list leads achslint to read: itself and the lists its entries name."""
    entries = [startup.default, startup.default_channel, *startup.axes, *startup.channels]
    return [startup.path, *(entry.path for entry in entries if entry is not None and entry.path is not None)]


def machine_files(startup: Path, cnc_root: Path | None = None, config_file: str | None = None) -> list[Path]:
    """The files a machine's start-up list leads achslint to read, with the configuration that applies to
    it (`config_file`, else the one found above it; its `cnc-root` unless `cnc_root` is given): for the
    check that a report or plot file is none of them. Nothing when the start-up list cannot be read (the
    run says so itself). Raises `ConfigError`."""
    config = load_file(Path(config_file)) if config_file else discover(startup)
    root = cnc_root or config.cnc_root()
    try:
        files = startup_files(read_startup(startup, None, root, "as given" if root else ""))
    except (OSError, UnreadableInput):
        return []
    return files + ([config.path] if config.path is not None else [])


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
    startups = {os.path.realpath(s.path): (s.path, s.root) for s in run.startups}
    for path in run.program_startups:  # found in the linted folders
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
        from .linting.program import lint_program_bytes
        from .machine.build import MachineError, build_machine  # only for machines with programs

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
            result = lint_program_bytes(data, machine, _shown(path), settings)
            outcome.results.append(result)


def _configured_program(path: Path) -> tuple[bytes | None, str]:
    """(the bytes, "") of a file a configuration names as a homing program, read once; (None, why) when it
    is none (not a regular file, too large, binary or UTF-16). Its lines are never shown."""
    from .core.files import read_program_file
    from .machine.program import program_text

    try:
        data = read_program_file(path)
    except Refused as exc:
        return None, str(exc)
    except OSError as exc:
        return None, f"cannot read {_shown(path)}: {reason(exc)}"
    if program_text(data) is None:
        return None, f"{_shown(path)} is not an NC program (it is not text: binary, or UTF-16); not checked"
    return data, ""


@dataclass
class FormatRequest:
    paths: list[str]
    config_file: str | None = None
    stdin_filename: str | None = None
    mode: str = "write"  # write | check (change nothing) | diff (change nothing, say how)


@dataclass
class Formatted:
    name: str
    changed: bool
    written: bool = False
    diff: str = ""  # mode diff: the unified diff
    output: bytes | None = None  # standard input in write mode: the formatted bytes


@dataclass
class FormatOutcome:
    results: list[Formatted]
    errors: list[str]
    notes: list[str]
    found: int  # lists found (XML files found in folders are not fmt's business and not counted)

    @property
    def changed(self) -> int:
        return sum(result.changed for result in self.results)

    @property
    def written(self) -> int:
        return sum(result.written for result in self.results)


def run_format(request: FormatRequest, stdin: BinaryIO | None = None) -> FormatOutcome:
    """`achslint fmt`: format every list the paths name, writing (atomically, only if the file did not
    change meanwhile), checking or diffing. Raises `ConfigError`."""
    from .fmt import format_bytes, unified_diff

    found = LintRun(
        LintRequest(
            paths=request.paths, config_file=request.config_file, stdin_filename=request.stdin_filename
        )
    ).discover()
    outcome = FormatOutcome([], list(found.errors), list(found.notes), len(found.targets))
    for target in found.targets:
        if is_xml(target.name):
            if target.name in request.paths:  # XML found in a folder is simply not fmt's business
                outcome.errors.append(f"{target.name}: fmt rewrites plain lists only, not XML files")
            continue
        try:
            if target.path is not None:
                data = read_list(target.path)
            elif stdin is not None:
                data = stdin.read()
            else:
                outcome.errors.append(f"{target.name}: no standard input to read")
                continue
            formatted, differs = format_bytes(data, target.name, target.config.settings.fmt)
        except OSError as exc:
            outcome.errors.append(f"cannot read {target.name}: {reason(exc)}")
            continue
        except UnreadableInput as exc:
            outcome.errors.append(f"{target.name}: {exc}")
            continue
        result = Formatted(target.name, differs)
        if request.mode == "diff":
            result.diff = unified_diff(data, formatted, target.name) if differs else ""
        elif request.mode == "write" and target.path is None:
            result.output = formatted
        elif request.mode == "write" and differs and target.path is not None:
            try:
                write_atomically(target.path, formatted, expected=data)
                result.written = True
            except OSError as exc:
                outcome.errors.append(write_error(exc, target.name))
        outcome.results.append(result)
    return outcome


def _as_bytes(source: Source) -> tuple[bytes, str]:
    """The bytes and display name of a list given as a path (str or Path) or as bytes.

    A string is a path (`FileNotFoundError` when there is no such file), never list text: use `lint_text`
    and `loads` for text. Only a string with a line break, which cannot be a file name, is still read as
    list text, for callers written before `lint_text` existed.
    """
    if isinstance(source, (bytes, bytearray)):
        return bytes(source), "<bytes>"
    if isinstance(source, str) and "\n" in source:
        return text_bytes(source), "<string>"
    path = Path(source)
    if not path.is_file():
        raise FileNotFoundError(2, "no such axis list", str(path))
    return read_list(path), str(path)


def lint(
    source: Source,
    *,
    select: Iterable[str] | None = None,
    ignore: Iterable[str] | None = None,
    name: str | None = None,
) -> list[Diagnostic]:
    """Diagnostics for one list (a path or bytes), with the built-in defaults and no config files."""
    data, default_name = _as_bytes(source)
    settings = FileSettings.of(list(select) if select else None, list(ignore or []))
    return findings(data, name or default_name, settings)


def lint_text(
    text: str,
    *,
    filename: str = "<string>",
    select: Iterable[str] | None = None,
    ignore: Iterable[str] | None = None,
) -> list[Diagnostic]:
    """Diagnostics for the text of one list, reported under `filename` (built-in defaults, no config files)."""
    settings = FileSettings.of(list(select) if select else None, list(ignore or []))
    return findings(text_bytes(text), filename, settings)


def load(source: Source, *, defaults: Source | None = None, strict: bool = False) -> AxisBase:
    """The typed model of a list (a path or bytes) on top of an optional default list.

    Lenient by default: the findings of `lint` are kept on the model (`model.findings`). With
    `strict=True` every error-level finding is raised as one pydantic `ValidationError`. A missing path
    raises `FileNotFoundError`.
    """
    from .model import build_model, rule_errors

    data, name = _as_bytes(source)
    default_data = _as_bytes(defaults) if defaults is not None else None
    return _finish(build_model(data, name, default_data), data, name, default_data, strict, rule_errors)


def _finish(
    model: AxisBase,
    data: bytes,
    name: str,
    default_data: tuple[bytes, str] | None,
    strict: bool,
    rule_errors: Callable[[list[Diagnostic]], Exception],
) -> AxisBase:
    settings = FileSettings(keep_source=False)
    found = lint_file(data, name, settings, default_data[0] if default_data else None).diagnostics
    model._findings = found
    errors = [d for d in found if d.severity is Severity.ERROR]
    if strict and errors:
        raise rule_errors(errors)
    return model


def loads(
    text: str, *, defaults: str | None = None, strict: bool = False, filename: str = "<string>"
) -> AxisBase:
    """The typed model of a list's text (see `load`)."""
    from .model import build_model, rule_errors

    data = text_bytes(text)
    default_data = (text_bytes(defaults), "<defaults>") if defaults is not None else None
    return _finish(
        build_model(data, filename, default_data), data, filename, default_data, strict, rule_errors
    )


def dumps(model: AxisBase) -> str:
    """A list in the canonical layout from a model (for lists generated by configuration tools):
    `loads(dumps(model))` gives an equal model."""
    from .fmt import canonical_text
    from .model import dumps as model_dumps

    return canonical_text(model_dumps(model))


def explain(source: Source, *, gear: int = 0, defaults: Source | None = None) -> ListReport:
    """What `achslint explain FILE --format json` prints: strategy, phases, corrections, homing parameters."""
    from .explanation import explain_list

    data, name = _as_bytes(source)
    return explain_list(data, name, gear, _as_bytes(defaults)[0] if defaults is not None else None)


def dry_run(source: Source, scenario: dict[str, Any] | None = None, *, gear: int = 0) -> DryRun:
    """Simulate the homing of a list (path or bytes); `scenario` as in a scenario file (mm / degrees,
    seconds). Returns the run: `.trace` holds the phases, events and the outcome."""
    from .dryrun import dry_run as simulate
    from .homing.scenario import parse_input

    data, name = _as_bytes(source)
    return simulate(data, name, parse_input(dict(scenario or {}), "scenario"), gear=gear)


def format_text(text: str) -> str:
    """The text of a list as `achslint fmt` writes it (whitespace only)."""
    from .fmt import format_text as formatted

    return formatted(text)


__all__ = [
    "ConfigError",
    "LintOutcome",
    "LintRequest",
    "LintRun",
    "dry_run",
    "dumps",
    "explain",
    "format_text",
    "lint",
    "lint_text",
    "load",
    "loads",
    "run_lint",
]

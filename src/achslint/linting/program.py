"""Lint of homing programs against a machine: `achslint lint rfp.nc --machine hochlauf.lis` (LIS6xx).

A program rule is a module with a `check_program(program, machine)` generator of diagnostics (see
`rules/__init__.py`); this module reads the program and the machine, runs the program rules through the
lint engine (with the `noqa` directives of the program's comments, so LIS009 reports the unused ones) and
hands back an ordinary `FileResult`, so every output format reports program findings like list findings.
What the rules share (where each axis stands, homed or not, before each block) is in `programcontext`.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

from ..core.diagnostics import Diagnostic
from ..machine.model import ChannelView, Program
from ..rules import Scope
from ..syntax.parser import split_lines
from .discovery import is_startup
from .engine import run
from .linter import FileResult, FileSettings
from .suppression import Suppressions


def check_program(
    program: Program, machine: ChannelView, settings: FileSettings | None = None
) -> list[Diagnostic]:
    """The findings of the enabled program rules (LIS6xx), severities overridden as configured, sorted; no
    `noqa` applied (`lint_program_on` applies the program's)."""
    return run(Scope.PROGRAM, (program, machine), (settings or FileSettings()).policy)


def lint_program(
    path: Path,
    startup: Path,
    *,
    name: str | None = None,
    cnc_root: Path | None = None,
    channel: int = 1,
    settings: FileSettings | None = None,
) -> FileResult:
    """Lint one homing program against the machine of a start-up list.

    A program that cannot be read gives a `FileResult` with `error` set; a machine that cannot be built
    raises `machinebuild.MachineError` (its message names the file and line).
    """
    from ..machine.build import build_machine

    machine = build_machine(startup, cnc_root=cnc_root, channel=channel)
    return lint_program_on(path, machine, name=name, settings=settings)


def lint_program_on(
    path: Path, machine: ChannelView, *, name: str | None = None, settings: FileSettings | None = None
) -> FileResult:
    """Lint one homing program against a machine that is already built."""
    from ..core.files import Refused, not_a_list_file, read_program_file, reason

    shown = name or str(path)
    settings = settings or FileSettings()
    problem = not_a_list_file(path)
    if problem is not None:
        return FileResult(shown, [], f"cannot read {shown}: {problem}")
    try:
        data = read_program_file(path)
    except Refused as exc:
        return FileResult(shown, [], str(exc))
    except OSError as exc:
        return FileResult(shown, [], f"cannot read {shown}: {reason(exc)}")
    return lint_program_bytes(data, machine, shown, settings)


def lint_program_bytes(data: bytes, machine: ChannelView, name: str, settings: FileSettings) -> FileResult:
    """Lint the bytes of one homing program (already read) against a machine that is already built."""
    from ..machine.program import program_text, read_program

    program = read_program(data, name)
    text = split_lines(program_text(data) or "")
    found = run(
        Scope.PROGRAM, (program, machine), settings.policy, suppressions=Suppressions.of_program(text, name)
    )
    lines = text if found and settings.keep_source else []
    return FileResult(name, found, None, lines, fail_on=settings.fail_on)


def lint_programs(
    paths: list[str],
    startup: Path | None,
    settings_for: Callable[[Path], FileSettings],
    *,
    cnc_root: Path | None = None,
    channel: int = 1,
) -> tuple[list[FileResult], list[str]]:
    """Lint NC programs against the machine of a start-up list (`--machine`, None when not given): (results,
    errors for exit code 2)."""
    from ..machine.build import MachineError, build_machine

    if startup is None:
        return _not_checked(
            paths,
            "an NC program is checked against a machine: give its start-up list with --machine hochlauf.lis",
        )
    if startup.is_file() and not is_startup(startup):  # an axis list would be a machine of no axes
        return _not_checked(
            paths,
            f"not checked: --machine {startup}: this is not a start-up list (it names no axis lists, "
            "achs_mds[i]); give the machine's start-up list (hochlauf.lis)",
        )
    try:
        machine = build_machine(startup, cnc_root=cnc_root, channel=channel)
    except MachineError as exc:
        return _not_checked(paths, f"not checked, the machine cannot be read: --machine: {exc}")
    results: list[FileResult] = []
    errors: list[str] = []
    for raw in paths:
        path = Path(raw)
        result = lint_program_on(path, machine, name=raw, settings=settings_for(path))
        if result.error:
            errors.append(result.error)
        results.append(result)
    return results, errors


def _not_checked(paths: list[str], why: str) -> tuple[list[FileResult], list[str]]:
    """Programs that could not be checked: each is an unreadable result (so no format reports the run as
    clean), and the reason is one error line per program."""
    errors = [f"{path}: {why}" for path in paths]
    return [FileResult(path, [], error) for path, error in zip(paths, errors, strict=True)], errors

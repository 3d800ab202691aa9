"""Lint of homing programs against a machine: `achslint lint rfp.nc --machine hochlauf.lis` (LIS6xx).

A program rule is a module with a `check_program(program, machine)` generator of diagnostics (see
`rules/__init__.py`); this module reads the program and the machine, runs the program rules through the
lint engine (with the `noqa` directives of the program's comments, so LIS009 reports the unused ones) and
hands back an ordinary `FileResult`, so every output format reports program findings like list findings.
The helpers the rules share live here too: where each axis stands (homed or not) before each block.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

from .diagnostics import Diagnostic, Related, Severity
from .lintengine import run
from .linter import FileResult, FileSettings
from .machinemodel import HomingBlock, Location, Machine, MachineAxis, MoveBlock, Program
from .rules import Scope
from .suppression import Suppressions
from .syntax import split_lines

if TYPE_CHECKING:
    from .api import LintRequest


def diagnostic(
    code: str,
    at: Location,
    message: str,
    severity: Severity,
    related: tuple[Related, ...] = (),
    parameter: str | None = None,
    p_axis: str | None = None,
) -> Diagnostic:
    """A program finding at a place of the program (one character wide when the end is not known)."""
    end = at.end_column if at.end_column is not None and at.end_column > at.column else at.column + 1
    return Diagnostic(
        at.path, at.line, at.column, at.line, end, code, severity, message, parameter, p_axis, related
    )


def defined(axis: MachineAxis) -> tuple[Related, ...]:
    """Where the machine defines an axis's name, as a related location."""
    at = axis.defined_at
    if at is None:
        return ()
    return (Related(at.path, at.line, at.column, None, f"{axis.name} is defined here"),)


def homing_blocks(program: Program) -> Iterator[HomingBlock]:
    """The G74 blocks of a program, in order."""
    return (block for block in program.blocks if isinstance(block, HomingBlock))


# -- the homing state before each block ---------------------------------------------------------------


def homed_from_start(axis: MachineAxis) -> bool:
    """Axes whose position is valid at power-up: an absolute encoder (P-AXIS-00014), which IGNORE_ABS_POS
    and DISABLED require."""
    return bool(axis.resolved.get("kenngr.abs_pos_gueltig")) or axis.resolved.homing_type in (
        "IGNORE_ABS_POS",
        "DISABLED",
    )


def homes_with_master(axis: MachineAxis) -> bool:
    """A gantry slave whose own homing is suppressed (P-AXIS-00074): referenced when its master is."""
    return axis.gantry_master is not None and bool(axis.resolved.get("kenngr.gantry_slave_no_homing"))


@dataclass(frozen=True)
class Step:
    """A block of the program with the axes homed before it runs."""

    block: HomingBlock | MoveBlock
    homed: frozenset[str]


def steps(program: Program, machine: Machine) -> Iterator[Step]:
    """The homing and move blocks in order, each with the names of the axes homed before it.

    A G74 block homes the machine axes it names (DISABLED axes excepted: the CNC stops there), and with a
    master its slaves whose own homing is suppressed. Skipped blocks change nothing.
    """
    homed = {name for name, axis in machine.axes.items() if homed_from_start(axis)}
    for block in program.blocks:
        if not isinstance(block, (HomingBlock, MoveBlock)):
            continue
        yield Step(block, frozenset(homed))
        if isinstance(block, HomingBlock):
            for word in block.words:
                axis = machine.axes.get(word.name)
                if axis is not None and axis.resolved.homing_type != "DISABLED":
                    homed.add(axis.name)
            for axis in machine.axes.values():
                if homes_with_master(axis) and axis.gantry_master in homed:
                    homed.add(axis.name)


# -- running the rules -----------------------------------------------------------------------------


def check_program(
    program: Program, machine: Machine, settings: FileSettings | None = None
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
    from .machinebuild import build_machine

    machine = build_machine(startup, cnc_root=cnc_root, channel=channel)
    return lint_program_on(path, machine, name=name, settings=settings)


def lint_program_on(
    path: Path, machine: Machine, *, name: str | None = None, settings: FileSettings | None = None
) -> FileResult:
    """Lint one homing program against a machine that is already built."""
    from .files import Refused, not_a_list_file, read_program_file, reason
    from .ncprogram import program_text, read_program

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
    program = read_program(data, shown)
    text = split_lines(program_text(data) or "")
    found = run(
        Scope.PROGRAM, (program, machine), settings.policy, suppressions=Suppressions.of_program(text, shown)
    )
    lines = text if found and settings.keep_source else []
    return FileResult(shown, found, None, lines, fail_on=settings.fail_on)


def lint_programs(
    paths: list[str], request: LintRequest, settings_for: Callable[[Path], FileSettings]
) -> tuple[list[FileResult], list[str]]:
    """Lint the NC programs a lint request names against its machine: (results, errors for exit code 2)."""
    from .machinebuild import MachineError, build_machine

    if request.machine is None:
        return _not_checked(
            paths,
            "an NC program is checked against a machine: give its start-up list with --machine hochlauf.lis",
        )
    cnc_root = Path(request.overrides.cnc_root) if request.overrides.cnc_root else None
    try:
        machine = build_machine(Path(request.machine), cnc_root=cnc_root, channel=request.channel)
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

"""What a homing-program rule (LIS6xx) sees besides the program and the machine: where a finding goes, where
the machine defines an axis, the program's G74 blocks, and which axes are homed before each block.

The program counterpart of `context.py` (what a list rule sees). The rules import it inside
`check_program`, so that a lint of lists does not load it.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass

from ..core.diagnostics import Diagnostic, Related, Severity
from ..homing.registry import classify
from ..machine.model import ChannelView, HomingBlock, Location, MachineAxis, MoveBlock, Program


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
    """Axes a program may count as homed before any G74 (an absolute encoder, P-AXIS-00014, or a homing type
    G74 leaves alone): what the axis's power-up strategy says."""
    return classify(axis.resolved).referenced_from_start


def homes_with_master(axis: MachineAxis) -> bool:
    """A gantry slave referenced when its master is (P-AXIS-00074): its strategy is homed with the master."""
    return axis.gantry_master is not None and classify(axis.resolved).definition.homed_with_master


def homed_by_g74(axis: MachineAxis) -> bool:
    """Whether a G74 naming the axis homes it (the strategy a G74 runs does not refuse it, as DISABLED does)."""
    return not classify(axis.resolved, commanded=True).definition.refuses_g74


@dataclass(frozen=True)
class Step:
    """A block of the program with the axes homed before it runs."""

    block: HomingBlock | MoveBlock
    homed: frozenset[str]


def steps(program: Program, machine: ChannelView) -> Iterator[Step]:
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
                if axis is not None and homed_by_g74(axis):
                    homed.add(axis.name)
            for axis in machine.axes.values():
                if homes_with_master(axis) and axis.gantry_master in homed:
                    homed.add(axis.name)

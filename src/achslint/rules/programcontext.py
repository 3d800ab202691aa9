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
from ..machine.model import (
    AxisWord,
    ChannelView,
    HomingBlock,
    Location,
    MachineAxis,
    MoveBlock,
    NamedAxis,
    Program,
    SkippedBlock,
)


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


def g74_words(program: Program) -> Iterator[tuple[AxisWord | NamedAxis, ...]]:
    """The axis words of every G74 block, in order: those whose homing order the reader knows (`AxisWord`)
    and those of a G74 whose order is computed when the program runs (`NamedAxis`)."""
    for block in program.blocks:
        if isinstance(block, HomingBlock):
            yield block.words
        elif isinstance(block, SkippedBlock) and block.homes:
            yield block.homes


def named_words(block: HomingBlock | MoveBlock | SkippedBlock) -> tuple[AxisWord | NamedAxis, ...]:
    """The axis words a block homes or moves (none for a block that does neither)."""
    if isinstance(block, HomingBlock):
        return block.words
    if isinstance(block, MoveBlock):
        return block.targets
    return block.homes + block.moves


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

    block: HomingBlock | MoveBlock | SkippedBlock  # skipped: a G74 or move whose values are computed
    homed: frozenset[str]
    # Axes that a part of the program the reader does not follow (a subroutine call, a branch) may have
    # homed before the block, besides `homed`.
    maybe: frozenset[str] = frozenset()

    def unhomed(self, name: str) -> bool:
        """Whether the axis is not homed before the block, whatever the parts not followed did: only then
        may a finding say it is not homed."""
        return name not in self.homed and name not in self.maybe


def steps(program: Program, machine: ChannelView) -> Iterator[Step]:
    """The blocks that home or move axes, in order, each with the names of the axes homed before it.

    A G74 block homes the machine axes it names (DISABLED axes excepted: the CNC stops there), whether its
    homing order is written or computed, and with a master its slaves whose own homing is suppressed.
    Other skipped blocks change nothing, except those the reader does not follow: after a call (or a block
    that may run any NC code) every axis may be homed; after a loop or jump every axis some G74 of the
    program names may be. A branch (`$IF`) changes nothing here: the blocks after it may be passed by, so
    what they home is counted as homed, and an axis no G74 above homes is not homed on any way through.
    """
    homed = {name for name, axis in machine.axes.items() if homed_from_start(axis)}
    maybe: set[str] = set()
    named: set[str] | None = None  # the axes some G74 of the program names (found once)
    for block in program.blocks:
        if isinstance(block, SkippedBlock):
            if block.unfollowed == "any":
                maybe.update(machine.axes)
            elif block.unfollowed == "flow":
                if named is None:
                    named = {word.name for words in g74_words(program) for word in words}
                maybe.update(named)
            if block.unfollowed:
                for slave in machine.axes.values():
                    if homes_with_master(slave) and slave.gantry_master in maybe:
                        maybe.add(slave.name)
            if not (block.homes or block.moves):
                continue
        yield Step(block, frozenset(homed), frozenset(maybe - homed))
        if isinstance(block, MoveBlock) or not (isinstance(block, HomingBlock) or block.homes):
            continue
        for word in block.words if isinstance(block, HomingBlock) else block.homes:
            axis = machine.axes.get(word.name)
            if axis is not None and homed_by_g74(axis):
                homed.add(axis.name)
        for axis in machine.axes.values():
            if homes_with_master(axis) and axis.gantry_master in homed:
                homed.add(axis.name)

"""A machine as the homing program sees it: programmed axis names, logical axis numbers, gantry pairs.

Built from a start-up list (`hochlauf.lis`): its axis lists (with the default list underneath, as the CNC
loads them) and its channel lists (`sda_mds[i]`), which give each channel's programmed axis names and their
logical axis numbers (`gruppe[g].achse[i].bezeichnung` / `.log_achs_nr`, `spindel[i].bezeichnung` /
`.log_achs_nr`) and its gantry pairs (`synchro_data.koppel_gruppe[g].paar[i].log_achs_nr_master` /
`_slave`). Without a channel list the names come from each axis list's `kopf.log_achs_name` (and a mapping
in the machine scenario).

These value objects are the contract between the readers (start-up list, channel list, homing program)
and their users (the machine dry-run, LIS6xx, `explain` of a machine). The readers live in their own
modules; this module only holds the shapes.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Literal

from ..axis.resolved import ResolvedAxis


@dataclass(frozen=True)
class Location:
    """Where something was written: file, 1-based line, 1-based column and end column (exclusive)."""

    path: str
    line: int
    column: int = 1
    end_column: int | None = None


@dataclass
class MachineAxis:
    """One axis of the machine under the name the NC program uses for it."""

    name: str  # programmed name, upper case as the channel list spells it ("X", "Z1", "S1")
    logical_number: int  # log_achs_nr (channel list) == kopf.achs_nr of the axis list
    list_path: Path | None  # the axis list the start-up list names for it
    data: bytes  # the axis list as read
    defaults: bytes | None  # the default list loaded under it, if any
    resolved: ResolvedAxis  # what the CNC runs (layering, references, load-time corrections)
    channel: int | None = None  # 1-based channel number when the name comes from a channel list
    spindle: bool = False  # named in spindel[i] of the channel list (or a spindle by kopf.achs_typ)
    gantry_master: str | None = None  # programmed name of the master when this axis is a gantry slave
    defined_at: Location | None = None  # where the name was given (channel list line, or kopf.log_achs_name)


@dataclass
class ChannelView:
    """A machine's axes by the names one channel's programs use, and how they are coupled: what the homing
    program sees of the machine (`resolved.Machine` is the machine itself; `build.channel_view` makes this)."""

    startup: Path | None
    axes: dict[str, MachineAxis] = field(default_factory=dict)  # key: programmed name, upper case
    gantry_pairs: list[tuple[str, str]] = field(default_factory=list)  # (master name, slave name)
    notes: list[str] = field(default_factory=list)  # what could not be read or was assumed, in words
    channel: int | None = (
        None  # the channel whose names `axes` uses (1-based), when built from a channel list
    )
    channel_list: Path | None = None  # that channel's list
    # Axes of the start-up list that the channel does not name (or whose name was taken): not programmable
    # in this channel, still part of the machine (shown by `explain`). A gantry slave among them carries
    # `gantry_master` and a pair in `gantry_pairs`: it moves with its master (`followers()`).
    other_axes: list[MachineAxis] = field(default_factory=list)

    def by_number(self, logical_number: int) -> MachineAxis | None:
        return next((a for a in self.axes.values() if a.logical_number == logical_number), None)

    def followers(self) -> list[MachineAxis]:
        """Gantry slaves that are no programmable axis (in `other_axes`, coupled to a named master): a
        program cannot name them, they move with their master (P-AXIS-00070)."""
        return [axis for axis in self.other_axes if axis.gantry_master is not None]


# -- the homing program ------------------------------------------------------------------------


@dataclass(frozen=True)
class AxisWord:
    """An axis address in a block: `X1` in `G74 X1 Y1`, `Z200` in `G01 Z200`."""

    name: str  # upper case
    value: float  # G74: the sequence number (an integer >= 1); moves: the target or increment in mm / °
    at: Location


@dataclass(frozen=True)
class HomingBlock:
    """`N20 G74 X1 Y1 A2 B2 S3`: axes with the same sequence number home simultaneously, lower numbers
    first."""

    at: Location
    number: int | None  # the N number, if written
    words: tuple[AxisWord, ...]

    def groups(self) -> list[tuple[int, list[AxisWord]]]:
        """The sequence groups in the order they run: [(sequence number, words), ...]."""
        numbers = sorted({int(w.value) for w in self.words})
        return [(n, [w for w in self.words if int(w.value) == n]) for n in numbers]


@dataclass(frozen=True)
class MoveBlock:
    """`N15 G01 G90 Z200 F500`: a straight move between homing blocks. The modal state (G00/G01, G90/G91,
    F) is already resolved by the reader: each move block carries what is in effect for it."""

    at: Location
    number: int | None
    rapid: bool  # G00 (the axes' rapid speed) rather than G01 at `feed`
    absolute: bool  # G90 (targets) rather than G91 (increments)
    feed_mm_min: float | None  # F in effect (mm/min); None when no F was programmed before a G01
    targets: tuple[AxisWord, ...]


@dataclass(frozen=True)
class NamedAxis:
    """An axis address of a block the reader passes over, by name: `X[P1*2]` in a move to a computed position,
    `X1` and `Y[P2]` in a G74 whose homing order is computed."""

    name: str  # upper case
    written: str  # the word as written (shortened), for messages
    at: Location


# How much of the program's course a block leaves unknown (SkippedBlock.unfollowed); after each of them no
# modal value (G00/G01, G90/G91, F) is known:
# "any": it may run any NC code (a subroutine or macro call, a computed G code, an optional `/` block), so
#   after it any axis may be homed;
# "flow": it loops or jumps (`$FOR`, `$WHILE`, `$GOTO`, …), so the blocks of the program may run in another
#   order, more than once or not at all;
# "branch": it may pass blocks after it by (`$IF`, `$ELSE`, `$SWITCH`, a computed M code that may end the
#   program): those may not run, but nothing runs twice or before a block written above it.
Unfollowed = Literal["any", "flow", "branch"]


@dataclass(frozen=True)
class SkippedBlock:
    """A block the dry-run does not simulate (listed with its line; nothing is guessed).

    Some of them still matter to the program's findings: a G74 whose homing order is computed homes the axes
    it names (`homes`), a move to a computed position moves its axes (`moves`), and after a block the reader
    does not follow (`unfollowed`) it no longer knows which axes are homed."""

    at: Location
    text: str
    reason: str
    homes: tuple[NamedAxis, ...] = ()
    moves: tuple[NamedAxis, ...] = ()
    unfollowed: Unfollowed | None = None

    @property
    def opaque(self) -> bool:
        """Whether the machine's state after this block is not known to the reader (the dry-run stops here)."""
        return bool(self.homes or self.moves or self.unfollowed)


@dataclass(frozen=True)
class ProgramProblem:
    """A defect of the program text itself (unterminated comment, G74 without axes, bad sequence number)."""

    at: Location
    message: str


@dataclass
class Program:
    """A homing program (`rfp.nc` or any NC program with G74 blocks) as far as the dry-run reads it."""

    name: str
    blocks: list[HomingBlock | MoveBlock | SkippedBlock] = field(default_factory=list)
    problems: list[ProgramProblem] = field(default_factory=list)
    end: Location | None = None  # M30 / M02, when present

"""The machine dry-run: a homing program (`rfp.nc`) run over all axes of a machine.

How the program runs (TF5200 homing manual §2.2, P-AXIS-00074, P-AXIS-00299):

* A `G74` block homes its axes in sequence groups: the axes with the lowest sequence number first, all of
  them at the same time, each with the single-axis simulation (the strategy's sequence over
  homing/motion.py, in the axis's own units: mm, or degrees on rotary axes and spindles); the next group
  starts when the slowest axis of the group has stopped. A flying spindle ends its group at its reference event and keeps turning.
* A move block (`G00`/`G01`, `G90`/`G91`, `F` in mm/min) is one straight interpolated move of all the axes
  it names, from rest to rest with a trapezoidal speed profile: at F (G01) or at the axes' rapid speed
  `getriebe[0].vb_eilgang` (G00), each axis within its `dynamik.vb_max` (and `vb_not_referenced` while it
  is not homed), with the linear slope's acceleration min(`lslope_profil.a_grenz_stufe_1`, `_stufe_2`)
  of each axis, scaled to the path so that no axis exceeds its own.
* A `G90` word of a modulo rotary axis (MODULO bit of `kenngr.achs_mode`, P-AXIS-00015; range
  `getriebe[0].modulou..moduloo`, P-AXIS-00127/00126) is a position within one revolution, reached the
  short way (the ISG convention for a modulo axis programmed without a direction word): from 350° to `A10`
  the axis turns +20°, not -340°; exactly half a revolution away it turns in the positive direction.
  The positions the run reports for such an axis are wrapped into its modulo range.
* Positions carry over from block to block. Before an axis is homed they are its actual values (the
  scenario's frame, as in the single-axis dry-run); the homing gives the offset to the homed frame, in
  which `G90` targets of a homed axis are read. After homing the axis stands where its braking left it.
* A gantry slave whose own homing is suppressed (P-AXIS-00074) moves with its master and is homed with it
  (it takes its own `pos_refpkt`); one that homes itself does so after its master, which then follows it.
  A slave named on its own with suppressed homing does not move. A static gantry slave the channel does
  not name (it belongs to no channel, P-AXIS-00070) is no axis a program may name (a block naming it
  stops the program), but it moves with its master all the same, and a G74 of the master homes it too
  (after the master when its own homing is not suppressed).
* An axis with homing type `IGNORE_ABS_POS` stands still while the others of its group move (the manual
  warns that nothing then prevents a collision); one with `DISABLED` stops the program with P-ERR-50686.
  An axis with an absolute encoder and another homing type runs that homing type when G74 names it.
* The first failure stops the program as the CNC does: the axes still moving brake with their own
  acceleration, and every later group and block is "not run".
* The run follows the program only as far as the reader knows what it does to the axes: at a subroutine or
  macro call, a control statement (`$IF`, `$GOTO`, …), a G74 whose homing order or a move whose position
  is computed, it stops, says so (a note at that line), and every block from there on is "not simulated".

`run_machine` runs it once; `MachinePlan` prepares the axes once and runs them many times (`sweep`).
The JSON document of a run is described in docs/dry-run/machine.md.
"""

from __future__ import annotations

import math
import random
import statistics
from collections import Counter
from collections.abc import Mapping
from dataclasses import dataclass, field
from decimal import Decimal
from pathlib import Path
from typing import Any

from ..catalogue.units import unit_label
from ..dryrun import DryRunRefused, finish, refusal
from ..homing import VELOCITY, HomingStrategy, classify
from ..homing.motion import Segment, Simulator, Trace, trapezoid
from ..homing.scenario import SWITCH_MARGIN, Scenario, ScenarioError
from ..rules.lis507_gantry_master_chain import CODE as CHAIN_CODE
from ..rules.lis507_gantry_master_chain import CouplingFault, circle_words, coupling_faults
from .model import (
    AxisWord,
    ChannelView,
    HomingBlock,
    Location,
    MachineAxis,
    MoveBlock,
    Program,
    SkippedBlock,
)
from .scenario import MachineScenario

VERSION = 1
DISABLED_ERROR = "P-ERR-50686"
COLLISION_NOTE = (
    "stands still (homing type IGNORE_ABS_POS) while the other axes of its group move: the CNC does not "
    "stop them, so make sure nothing can collide"
)


# --- the result ---------------------------------------------------------------------------------


@dataclass
class AxisPhase:
    """A stretch of one axis's motion in machine time (seconds from the program start)."""

    name: str
    kind: str  # "homing", "move", "following", "still"
    block: int  # index into MachineRun.blocks
    start_time: float
    end_time: float
    start_position: float  # actual values (the scenario's frame), like the single-axis trace
    end_position: float
    velocity: float  # commanded speed, unit/s
    direction: str | None
    ended_by: str
    segments: list[Segment] = field(default_factory=list)


@dataclass
class AxisRun:
    """What happened to one axis over the whole program."""

    name: str
    logical_number: int
    unit: str
    strategy: HomingStrategy
    scenario: Scenario
    start_position: float
    position: float  # where it stands at the end, actual value (scenario frame)
    offset: float | None = None  # homed value = actual value + offset, once homed
    outcome: str = "not_commanded"  # homed, failed, aborted, not_run, skipped, not_simulated, not_commanded
    failure: str | None = None
    reference: dict[str, Any] | None = None  # kind, position (actual), value, time
    gantry: tuple[str, str] | None = None  # ("master" | "slave", partner's name)
    spindle: bool = False
    ends_moving: bool = False  # a flying spindle keeps turning after its reference
    phases: list[AxisPhase] = field(default_factory=list)
    warnings: list[dict[str, Any]] = field(default_factory=list)
    traces: list[tuple[float, Trace]] = field(default_factory=list)  # single-axis traces and their start

    @property
    def homed(self) -> bool:
        return self.offset is not None

    def shown(self, position: float) -> float:
        """A position as the run reports it: on a modulo axis wrapped into its modulo range [low, high),
        elsewhere unchanged (the run itself counts on past the range, so a move's distance is its end minus
        its start)."""
        modulo = self.strategy.setup.modulo
        if not modulo:
            return position
        return _wrap(position, modulo)

    @property
    def final_position(self) -> float | None:
        """Where the axis stands at the end in the homed frame (None while it is not homed)."""
        if self.offset is None:
            return None
        return self.shown(self.position + self.offset)

    def warn(self, code: str | None, message: str) -> None:
        self.warnings.append({"code": code, "message": message})


@dataclass
class GroupRun:
    """One sequence group of a G74 block: the axes that home at the same time."""

    sequence: int
    axes: list[str]
    start_time: float | None = None
    end_time: float | None = None
    outcome: str = "not_run"  # done, failed, not_run
    moving: list[str] = field(default_factory=list)
    still: list[str] = field(default_factory=list)
    following: list[str] = field(default_factory=list)


@dataclass
class BlockRun:
    index: int
    kind: str  # "homing", "move", "skipped"
    text: str  # the block as the dry-run read it ("N20 G74 X1 Y1 A2 B2 S3")
    at: Location
    number: int | None
    axes: list[str]
    start_time: float | None = None
    end_time: float | None = None
    outcome: str = "not_run"  # done, failed, not_run, not_simulated
    groups: list[GroupRun] = field(default_factory=list)
    note: str | None = None


@dataclass
class MachineFailure:
    """The failure that stopped the program."""

    axis: str | None
    reason: str  # in full
    cause: str  # without the numbers of this run (what sweeps count)
    time: float
    block: int
    at: Location
    code: str | None = None


@dataclass
class MachineRun:
    machine: ChannelView
    program: Program
    scenario: MachineScenario
    cycle_time: float  # s
    axes: dict[str, AxisRun]
    blocks: list[BlockRun]
    total_time: float = 0.0
    failure: MachineFailure | None = None
    warnings: list[dict[str, Any]] = field(default_factory=list)

    @property
    def outcome(self) -> str:
        return "failed" if self.failure else "done"

    def warn(self, code: str | None, message: str, at: Location | None = None) -> None:
        self.warnings.append({"code": code, "message": message, "line": at.line if at else None})


# --- preparing the axes -------------------------------------------------------------------------


class _Axis:
    """One axis prepared for many runs: strategy, completed scenario, simulator, move dynamics."""

    def __init__(self, axis: MachineAxis, scenario: MachineScenario, cycle_time_us: int):
        values = axis.resolved
        self.axis = axis
        self.name = axis.name
        self.strategy = classify(values, commanded=True)  # what a G74 that names the axis runs
        setup = self.strategy.setup
        given = scenario.given(axis.name)
        # Without a table of its own the axis took the machine-wide keys: say which axis refused them, and
        # where a key for this axis alone goes.
        where = (
            scenario.table(axis.name)
            if axis.name in scenario.axes
            else f"{scenario.where}: axis {axis.name} (the machine-wide keys; [axes.{axis.name}] overrides them)"
        )
        try:
            self.scenario = self.strategy.default_scenario(given, cycle_time_us, name=axis.name)
        except ScenarioError as exc:
            raise ScenarioError(f"{where}: {str(exc).removeprefix('scenario: ')}") from None
        self.simulator = Simulator(values, self.strategy, self.scenario)
        self.unit = setup.unit
        self.spindle = setup.spindle or axis.spindle
        self.modulo = setup.modulo
        self.soft_limits = setup.soft_limits
        self.reference_position = setup.reference_position
        self.absolute = setup.absolute
        self.vmax = values.number("getriebe[0].dynamik.vb_max") * VELOCITY
        self.rapid = min(values.number("getriebe[0].vb_eilgang") * VELOCITY, self.vmax)
        self.unreferenced = setup.unreferenced_limit
        self.move_acceleration = float(
            min(
                values.number("getriebe[0].lslope_profil.a_grenz_stufe_1"),
                values.number("getriebe[0].lslope_profil.a_grenz_stufe_2"),
            )
            or 1.0
        )
        self.braking = float(self.simulator.acceleration or self.move_acceleration)
        self._refused: str | None = None
        self._refusal_known = False

    def refused(self) -> str | None:
        """The lint finding that makes the CNC refuse this axis's homing (LIS306, LIS319, LIS328), checked once."""
        if not self._refusal_known:
            self._refused = refusal(self.axis.data, self.axis.name, self.axis.defaults)
            self._refusal_known = True
        return self._refused

    def speed_limit(self, homed: bool) -> float:
        return float(self.vmax if homed else min(self.vmax, self.unreferenced))


class MachinePlan:
    """A machine, a program and a scenario, prepared once; `run` simulates (from other start positions)."""

    def __init__(
        self, machine: ChannelView, program: Program, scenario: MachineScenario, *, cycle_time_us: int = 1000
    ):
        if program.problems:
            first = program.problems[0]
            raise DryRunRefused(
                f"{first.at.path}:{first.at.line}:{first.at.column}: {first.message}; the CNC does not run "
                "this program (fix it, or see `achslint lint` for all its problems)"
            )
        followers = {axis.name: axis for axis in machine.followers()}
        scenario.check_names([*machine.axes, *followers])
        if scenario.cycle_time_ms is not None:
            cycle_time_us = round(scenario.cycle_time_ms * 1000)
        self.machine = machine
        self.program = program
        self.scenario = scenario
        self.cycle_time_us = cycle_time_us
        # The axes a program may name, and the gantry slaves outside the channel that move with their master.
        self.programmable = set(machine.axes)
        everyone = {**machine.axes, **followers}
        self.axes = {name: _Axis(axis, scenario, cycle_time_us) for name, axis in everyone.items()}
        coupled: dict[str, str] = {}  # slave -> master
        for master, slave in machine.gantry_pairs:
            coupled[slave.upper()] = master.upper()
        for name, axis in everyone.items():
            if axis.gantry_master and name not in coupled:
                coupled[name] = axis.gantry_master.upper()
        # Couplings without a master to lead them (LIS507) are not simulated: the axes involved are refused
        # when a block names them, every other axis runs.
        self.uncoupled: dict[str, str] = {}  # axis -> why the dry-run does not simulate it
        for slave, fault in coupling_faults(coupled).items():
            # each axis of a circle is a slave with its own fault; a chain takes the master along
            for name in fault.members[:2] if fault.kind == "chain" else (slave,):
                self.uncoupled.setdefault(name, _no_master(slave, fault))
        self.master = {
            s: m for s, m in coupled.items() if s not in self.uncoupled and m not in self.uncoupled
        }
        self.slaves: dict[str, list[str]] = {}
        for slave, master in self.master.items():
            self.slaves.setdefault(master, []).append(slave)

    def partners(self, name: str) -> list[str]:
        """The axes mechanically coupled to this one (its gantry slaves, or its master)."""
        found = list(self.slaves.get(name, []))
        if name in self.master:
            found.append(self.master[name])
        return [n for n in found if n in self.axes]

    def suppressed(self, name: str) -> bool:
        """A gantry slave whose own homing is suppressed (it is homed with its master)."""
        return name in self.master and self.axes[name].strategy.definition.homed_with_master

    def run(
        self, starts: Mapping[str, float] | None = None, cam_shifts: Mapping[str, float] | None = None
    ) -> MachineRun:
        return _Runner(self, starts or {}, cam_shifts or {}).run()


def _no_master(slave: str, fault: CouplingFault[str]) -> str:
    """Why the dry-run does not simulate the axes of a gantry coupling without a master (LIS507)."""
    if fault.kind == "itself":
        return (
            f"{slave} is its own gantry master (kenngr.gantry_ax_nr names its own logical axis number): no axis "
            f"leads this gantry, so the dry-run does not simulate {slave} ({CHAIN_CODE})"
        )
    if fault.kind == "circle":
        return (
            f"{circle_words(fault)} name each other as gantry master: no axis leads this gantry, so the dry-run "
            f"does not simulate them ({CHAIN_CODE})"
        )
    _, master, lead = fault.members
    return (
        f"{slave} follows the gantry master {master}, which is itself the gantry slave of {lead}: a slave of a "
        f"slave is no gantry the CNC couples, so the dry-run does not simulate {slave} and {master} ({CHAIN_CODE})"
    )


def run_machine(
    machine: ChannelView, program: Program, scenario: MachineScenario, *, cycle_time_us: int = 1000
) -> MachineRun:
    """Simulate the homing program over the machine once (see the module docstring).

    Raises DryRunRefused for a program the CNC would not start (its text problems) and ScenarioError for a
    scenario that does not fit the machine."""
    return MachinePlan(machine, program, scenario, cycle_time_us=cycle_time_us).run()


def machine_dry_run(
    startup: Path,
    program: Path,
    scenario: Path | None = None,
    *,
    channel: int = 1,
    config: Path | None = None,
    sweep_runs: int = 0,
) -> tuple[MachineRun, dict[str, Any] | None]:
    """`achslint dry-run hochlauf.lis --program rfp.nc`: build the machine from the start-up list (the
    configuration's `cnc-root`), read the program and the machine scenario (the configuration's `scenario`
    table and `cycle-time-us` underneath), run it, and sweep it `sweep_runs` times.

    Raises MachineError (machine or program unreadable), ScenarioError and DryRunRefused, each with a
    one-line message naming the file."""
    from ..core.files import Refused, read_program_file, reason
    from ..homing.scenario import ScenarioError
    from .build import MachineError, build_machine, rename
    from .program import read_program
    from .scenario import machine_scenario_input

    given, cycle_time_us, cnc_root = machine_scenario_input(startup, scenario, config)
    machine = build_machine(startup, cnc_root=cnc_root, channel=channel)
    try:
        rename(machine, given.names, given.where)
    except ValueError as exc:
        raise ScenarioError(str(exc)) from None
    if not machine.axes:
        raise MachineError(
            "names no axis lists (achs_mds[i]): --program needs the machine's start-up list (hochlauf.lis)",
            startup,
        )
    try:
        data = read_program_file(program)
    except Refused as exc:
        raise MachineError(str(exc)) from None  # the message names the file
    except OSError as exc:
        raise MachineError(f"cannot read the homing program: {reason(exc)}", program) from None
    read = read_program(data, str(program))
    moves = sum(1 for block in read.blocks if not isinstance(block, SkippedBlock))
    if moves > MAX_PROGRAM_MOVES:
        raise MachineError(
            f"has {moves:,} homing and motion blocks; the dry-run runs at most {MAX_PROGRAM_MOVES:,} (each keeps "
            "its axes' motion over time, and a homing program holds a few dozen): dry-run the part that homes",
            program,
        )
    plan = MachinePlan(machine, read, given, cycle_time_us=cycle_time_us)
    return plan.run(), (sweep(plan, sweep_runs) if sweep_runs else None)


# A machine dry-run keeps every block's motion (about 12 KB and 0.6 ms a block on a three-axis machine):
# 2,000 blocks are about a second and 25 MB; the 16 MB a program may have would be a million blocks.
MAX_PROGRAM_MOVES = 2_000


# --- one run ------------------------------------------------------------------------------------


def block_text(block: HomingBlock | MoveBlock | SkippedBlock) -> str:
    if isinstance(block, SkippedBlock):
        return block.text
    number = f"N{block.number} " if block.number is not None else ""
    if isinstance(block, HomingBlock):
        return f"{number}G74 " + " ".join(address(w.name) + str(int(w.value)) for w in block.words)
    words = ["G00" if block.rapid else "G01", "G90" if block.absolute else "G91"]
    words += [address(w.name) + programmed(w.value) for w in block.targets]
    if not block.rapid and block.feed_mm_min is not None:
        words.append(f"F{programmed(block.feed_mm_min)}")
    return number + " ".join(words)


def address(name: str) -> str:
    """An axis address as the program must write it: an extended name (with digits, `A1`) takes `=` before
    its value (`A1=2`), so that the text reads back as the block it came from (not `A12`)."""
    return f"{name}=" if any(character.isdigit() for character in name) else name


def programmed(value: float) -> str:
    """A number of the program as its shortest exact text, without exponent: `F0.00001` stays so (four
    decimals would show `F0`, a feed the block does not have)."""
    text = format(Decimal(repr(value)), "f")
    text = text.rstrip("0").rstrip(".") if "." in text else text
    return "0" if text == "-0" else text


def _num(value: float) -> str:
    """A computed number (a position, a limit) to four decimals."""
    text = f"{value:.4f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


def _wrap(position: float, modulo: tuple[float, float]) -> float:
    """A position brought into the modulo range [low, high)."""
    low, high = modulo
    value = low + (position - low) % (high - low)
    return low if value >= high else value  # a rounding of -1e-17 % 360 gives 360 itself


def _short_way(distance: float, modulo: tuple[float, float]) -> float:
    """The signed travel of a modulo axis to a position `distance` ahead of it (any number of revolutions):
    the shorter way round, within (-half, +half] of a revolution; a half revolution goes the positive way."""
    revolution = modulo[1] - modulo[0]
    ahead = distance % revolution  # [0, revolution)
    return ahead - revolution if ahead > revolution / 2 else ahead


def _dir(s: float) -> str | None:
    return "positive" if s > 0 else "negative" if s < 0 else None


def _position_at(phases: list[AxisPhase], t: float, default: float) -> float:
    for phase in phases:
        for segment in phase.segments:
            if segment.t0 <= t <= segment.t1:
                return segment.position(t)
    return default


def _cut(phases: list[AxisPhase], t: float, braking: float, why: str) -> bool:
    """Stop an axis at time t: the phase running then brakes with `braking`, later phases are dropped.
    True when the axis was still moving (or due to move) at t."""
    kept: list[AxisPhase] = []
    cut = False
    for phase in phases:
        if phase.end_time <= t:
            kept.append(phase)
            continue
        cut = True
        if phase.start_time >= t:
            continue
        segments: list[Segment] = []
        x, v = phase.start_position, 0.0
        for segment in phase.segments:
            if segment.t0 >= t:
                break
            end = min(segment.t1, t)
            segments.append(Segment(segment.t0, end, segment.x0, segment.v0, segment.a))
            x, v = segment.position(end), segment.velocity(end)
        end_time, end_position = t, x
        if abs(v) > 1e-12:
            stop = abs(v) / braking
            segments.append(Segment(t, t + stop, x, v, -math.copysign(braking, v)))
            end_time, end_position = t + stop, x + v * stop / 2
        phase.segments = segments
        phase.end_time, phase.end_position = end_time, end_position
        phase.ended_by = why
        kept.append(phase)
    phases[:] = kept
    return cut


def _time_at(distance: float, length: float, peak: float, t_acc: float, cruise: float, a: float) -> float:
    """When a trapezoidal move of `length` has covered `distance` (0 ≤ distance ≤ length)."""
    d_acc = peak * t_acc / 2
    if distance <= d_acc:
        return math.sqrt(2 * distance / a)
    if distance <= length - d_acc:
        return t_acc + (distance - d_acc) / peak
    return 2 * t_acc + cruise - math.sqrt(max(2 * (length - distance) / a, 0.0))


@dataclass
class _Leg:
    """One axis's homing within a group: its engine trace placed in machine time."""

    name: str
    start: float
    x_start: float
    trace: Trace
    phases: list[AxisPhase]
    fail_time: float | None
    ref_time: float | None
    followers: list[str]


class _Runner:
    def __init__(self, plan: MachinePlan, starts: Mapping[str, float], shifts: Mapping[str, float]):
        self.plan = plan
        self.shifts = shifts
        self.x: dict[str, float] = {}
        axes: dict[str, AxisRun] = {}
        for name, prepared in plan.axes.items():
            start = starts.get(name, prepared.scenario.start_position)
            self.x[name] = start
            role = None
            if name in plan.master:
                role = ("slave", plan.master[name])
            elif name in plan.slaves:
                role = ("master", ", ".join(plan.slaves[name]))
            axes[name] = AxisRun(
                name,
                prepared.axis.logical_number,
                prepared.unit,
                prepared.strategy,
                prepared.scenario,
                start,
                start,
                offset=0.0 if prepared.absolute else None,  # an absolute encoder knows its position
                gantry=role,
                spindle=prepared.spindle,
            )
        self.result = MachineRun(
            plan.machine,
            plan.program,
            plan.scenario,
            plan.cycle_time_us / 1e6,
            axes,
            [
                BlockRun(i, _kind(b), block_text(b), b.at, getattr(b, "number", None), _names(b))
                for i, b in enumerate(plan.program.blocks)
            ],
        )
        coupled = {slave for _, slave in plan.machine.gantry_pairs}
        for axis in plan.machine.other_axes:  # a gantry slave the run cannot couple is said, not dropped
            master = axis.resolved.get("kenngr.gantry_ax_nr")
            if isinstance(master, int) and master > 0 and axis.name not in coupled:
                where = f" ({axis.list_path})" if axis.list_path is not None else ""
                self.result.warn(
                    "LIS503",
                    f"{axis.name}{where} is the gantry slave of logical axis {master}, which this machine's "
                    "channel does not name (or no axis list has): the run cannot couple it, so it does not "
                    "move it",
                )

    # -- the program ---------------------------------------------------------------------------
    def run(self) -> MachineRun:
        result = self.result
        t = 0.0
        for index, block in enumerate(self.plan.program.blocks):
            record = result.blocks[index]
            record.start_time = t
            if isinstance(block, HomingBlock):
                t = self._homing(index, block, t)
            elif isinstance(block, MoveBlock):
                t = self._move(index, block, t)
            else:
                record.outcome, record.end_time, record.note = "not_simulated", t, block.reason
                if block.opaque:  # what it does to the axes is not known: the run cannot go on from here
                    self._unfollowed(index, block)
                    break
                continue
            record.end_time = t
            if result.failure is not None:
                record.outcome = "failed"
                break
            record.outcome = "done"
        for record in result.blocks:
            if record.outcome != "done":
                # a gantry slave moves with its master: what stays of the master's block stays of the slave's
                for name in [*record.axes, *(s for n in record.axes for s in self.plan.slaves.get(n, []))]:
                    axis = result.axes.get(name)
                    if axis is not None and axis.outcome == "not_commanded":
                        axis.outcome = "not_simulated" if record.outcome == "not_simulated" else "not_run"
        for name, axis in result.axes.items():
            axis.position = self.x[name]
        result.total_time = max(
            [t] + [p.end_time for axis in result.axes.values() for p in axis.phases if p.kind != "still"]
        )
        return result

    def _unfollowed(self, index: int, block: SkippedBlock) -> None:
        """The run stops following the program at a block whose effect on the axes the reader does not know
        (a subroutine call, a branch, a computed position or homing order): this block and every later one
        are not simulated, and the run says so."""
        note = f"not simulated: the run stops following the program at line {block.at.line}"
        for record in self.result.blocks[index + 1 :]:
            record.outcome, record.note = "not_simulated", note
        later = self.plan.program.blocks[index:]
        if any(isinstance(b, SkippedBlock) and b.unfollowed == "any" for b in later):  # may command any axis
            for axis in self.result.axes.values():
                if axis.outcome == "not_commanded":
                    axis.outcome = "not_simulated"
        self.result.warn(
            None,
            f"the run stops following the program here ({block.reason}): this block and every block after it "
            "are not simulated",
            block.at,
        )

    def _switches(self, name: str) -> tuple[float, float] | None:
        """The limit switches of an axis in actual values. Switches the scenario names stay where it puts them;
        assumed ones lie SWITCH_MARGIN beyond the software limits of the frame those hold in: the homed one once
        the axis is homed (its offset moves them), the actual values before. (Placed in actual values only, the
        switch of an axis whose reference point lies far from 0 fell inside its software limits after homing,
        and the manual's own program hit it moving to Z0.)"""
        prepared = self.plan.axes[name]
        switches = prepared.scenario.limit_switches
        offset = self.result.axes[name].offset
        if switches is None or offset is None or "limit_switches" not in prepared.scenario.assumed:
            return switches
        low, high = prepared.soft_limits
        return (low - SWITCH_MARGIN - offset, high + SWITCH_MARGIN - offset)

    def _fail(
        self,
        index: int,
        at: Location,
        axis: str | None,
        reason: str,
        t: float,
        cause: str | None = None,
        code: str | None = None,
    ) -> None:
        if self.result.failure is None:
            self.result.failure = MachineFailure(axis, reason, cause or reason, t, index, at, code)
            if axis in self.result.axes:
                run = self.result.axes[axis]
                run.outcome, run.failure = "failed", reason.removeprefix(f"{axis}: ")

    def _known(self, index: int, word: AxisWord, t: float, doing: str) -> bool:
        """Whether a word names an axis of the machine; if not, the program fails here (`doing` begins the
        reason: "G74 names A")."""
        name = word.name.upper()
        if name in self.plan.programmable:
            return True
        known = ", ".join(sorted(self.plan.programmable)) or "none"
        master = self.plan.axes[name].axis.gantry_master if name in self.plan.axes else None
        if master is not None:
            reason = (
                f"{doing}, the gantry slave of {master}: it is no axis of the channel (its axes: {known}) and "
                f"moves only with its master; program {master}"
            )
            self._fail(index, word.at, name, reason, t, "gantry slave named in the program")
            return False
        reason = f"{doing}, which is not an axis of the machine (its axes: {known})"
        self._fail(index, word.at, name, reason, t, "unknown axis name")
        return False

    # -- G74 ---------------------------------------------------------------------------------------
    def _homing(self, index: int, block: HomingBlock, t: float) -> float:
        record = self.result.blocks[index]
        record.groups = [GroupRun(n, [w.name.upper() for w in words]) for n, words in block.groups()]
        # A name the channel does not have, or a name the block repeats, stops the block before its first step
        # (LIS602, LIS603, as `explain`).
        seen: set[str] = set()
        for group, (_, words) in zip(record.groups, block.groups(), strict=True):
            for word in words:
                name = word.name.upper()
                if not self._known(index, word, t, f"G74 names {name}"):
                    group.start_time, group.end_time, group.outcome = t, t, "failed"
                    return t
                if name in seen:
                    self._fail(index, word.at, name, f"G74 names {name} twice", t, "axis named twice")
                    group.start_time, group.end_time, group.outcome = t, t, "failed"
                    return t
                seen.add(name)
        for group, (_, words) in zip(record.groups, block.groups(), strict=True):
            group.start_time = t
            t = self._group(index, group, words, t)
            group.end_time = t
            if self.result.failure is not None:
                group.outcome = "failed"
                break
            group.outcome = "done"
        return t

    def _check(self, index: int, words: list[AxisWord], t: float) -> bool:
        """What stops a group before anything moves: unknown or repeated names, DISABLED, refused homing."""
        seen: set[str] = set()
        plan = self.plan
        for word in words:
            name = word.name.upper()
            if not self._known(index, word, t, f"G74 names {name}"):
                return False
            if name in seen:
                self._fail(index, word.at, name, f"G74 names {name} twice", t, "axis named twice")
                return False
            seen.add(name)
            if name in plan.uncoupled:
                self._fail(index, word.at, name, plan.uncoupled[name], t, "gantry coupling without a master")
                return False
            prepared = plan.axes[name]
            if prepared.strategy.definition.refuses_g74:
                self._fail(
                    index,
                    word.at,
                    name,
                    f"{DISABLED_ERROR}: homing of {name} is DISABLED (kenngr.homing.homing_type); a G74 that "
                    "names it ends with an error and the program stops",
                    t,
                    "homing DISABLED",
                    DISABLED_ERROR,
                )
                return False
            refused = prepared.refused()
            if refused:
                self._fail(index, word.at, name, refused, t, "the CNC refuses this homing")
                return False
        return True

    def _group(self, index: int, group: GroupRun, words: list[AxisWord], t0: float) -> float:
        if not self._check(index, words, t0):
            return t0
        plan, axes = self.plan, self.result.axes
        names = group.axes
        first: list[str] = []
        after_master: list[str] = []
        alone: list[str] = []
        for name in names:
            master = plan.master.get(name)
            if plan.suppressed(name):
                if master not in names:
                    alone.append(name)
                continue  # moves and is homed with its master
            if master in names:
                after_master.append(name)  # a slave that homes itself does so after its master
            else:
                first.append(name)
        # A gantry slave outside the channel cannot be named: it homes with its master, after it when it
        # has a homing of its own (one whose homing is suppressed follows the master's, below).
        for name in first:
            for slave in plan.slaves.get(name, []):
                if slave not in plan.programmable and not plan.suppressed(slave) and slave not in names:
                    after_master.append(slave)
        legs: dict[str, _Leg] = {}
        for name in first:
            legs[name] = self._leg(index, name, t0)
        earliest = min((leg.fail_time for leg in legs.values() if leg.fail_time is not None), default=None)
        for name in after_master:
            lead = legs[plan.master[name]]
            start = lead.phases[-1].end_time if lead.phases else t0
            if earliest is not None and earliest < start:
                continue
            # It starts where following its master's homing left it.
            moved = (lead.phases[-1].end_position - lead.x_start) if lead.phases else 0.0
            leg = self._leg(index, name, start, self.x[name] + moved)
            legs[name] = leg
            if leg.fail_time is not None:
                earliest = leg.fail_time if earliest is None else min(earliest, leg.fail_time)
        # Failure: everything still moving then brakes; the failing axis is the one that failed first.
        if earliest is not None:
            failed = min(
                (leg for leg in legs.values() if leg.fail_time is not None),
                key=lambda leg: leg.fail_time if leg.fail_time is not None else math.inf,
            )
            self._fail(
                index,
                next((w.at for w in words if w.name.upper() == failed.name), words[0].at),
                failed.name,
                f"{failed.name}: {failed.trace.failure}",
                earliest,
                failed.trace.phases[-1].ended_by if failed.trace.phases else (failed.trace.failure or ""),
            )
            for leg in legs.values():
                why = f"stopped: {failed.name} failed"
                if leg is not failed and _cut(leg.phases, earliest, plan.axes[leg.name].braking, why):
                    axes[leg.name].outcome = "aborted"
                    axes[leg.name].failure = f"stopped when the homing of {failed.name} failed"
        end = t0
        for name, leg in legs.items():
            self._settle(leg, earliest, set(legs))
            if leg.phases:
                group.moving.append(name)
                end = max(end, leg.phases[-1].end_time)
            for follower in leg.followers:
                if follower not in group.following and follower not in legs:
                    group.following.append(follower)
                    if follower not in group.moving and leg.phases:
                        group.moving.append(follower)
        for name in names:
            if name in alone or (name in legs and not legs[name].phases):
                group.still.append(name)
        for name in alone:
            axes[name].outcome = "skipped"
            axes[name].warn(
                None,
                f"the homing of gantry slave {name} is suppressed (P-AXIS-00074): it is homed when its "
                f"master {plan.master[name]} is, not on its own",
            )
        others_move = bool(group.moving)
        for name in group.still if end > t0 else ():
            axes[name].phases.append(
                AxisPhase(
                    "standing still",
                    "still",
                    index,
                    t0,
                    end,
                    self.x[name],
                    self.x[name],
                    0.0,
                    None,
                    "stood still while its group homed" if others_move else "did not move",
                )
            )
            if others_move and plan.axes[name].strategy.definition.skipped_by_g74:
                message = f"{name} {COLLISION_NOTE} ({', '.join(group.moving)} moving)"
                axes[name].warn("LIS607", message)
                self.result.warn("LIS607", message, words[0].at)
        return end

    def _leg(self, index: int, name: str, start: float, x: float | None = None) -> _Leg:
        """Run one axis's homing from where it stands (or `x`), placed at `start`; its gantry partners
        follow it."""
        plan = self.plan
        prepared = plan.axes[name]
        x = self.x[name] if x is None else x
        trace = prepared.simulator.run(start=x, cam_shift=self.shifts.get(name, 0.0))
        finish(prepared.simulator, trace)
        phases = [
            AxisPhase(
                p.name,
                "homing",
                index,
                p.start_time + start,
                p.end_time + start,
                p.start_position,
                p.end_position,
                p.velocity,
                p.direction,
                p.ended_by,
                [Segment(s.t0 + start, s.t1 + start, s.x0, s.v0, s.a) for s in p.segments],
            )
            for p in trace.phases
        ]
        fail_time = None
        if trace.outcome == "failed":
            fail_time = start + (trace.phases[-1].segments[-1].t0 if trace.phases else 0.0)
        ref_time = None
        if trace.reference is not None:
            kind = trace.reference["kind"]
            times = [e.time for e in trace.events if e.kind.startswith(kind)]
            ref_time = start + (times[-1] if times else trace.total_time)
        followers = [p for p in plan.partners(name) if p != name]
        return _Leg(name, start, x, trace, phases, fail_time, ref_time, followers)

    def _settle(self, leg: _Leg, stop: float | None, homing: set[str]) -> None:
        """Record a leg (already cut at `stop`) on its axis and its followers, and move them; `homing` are
        the axes with a homing of their own in this group."""
        plan, axes = self.plan, self.result.axes
        name, trace = leg.name, leg.trace
        run = axes[name]
        run.traces.append((leg.start, trace))
        run.phases.extend(leg.phases)
        for warning in trace.warnings:
            if warning not in run.warnings:
                run.warnings.append(dict(warning))
        end_x = leg.phases[-1].end_position if leg.phases else leg.x_start
        full_end = trace.phases[-1].end_position if trace.phases else leg.x_start
        homed = (
            trace.outcome == "homed"
            and trace.reference is not None
            and leg.ref_time is not None
            and (stop is None or leg.ref_time <= stop)
        )
        moved = end_x - leg.x_start
        self.x[name] = end_x
        if homed and trace.final_position is not None and trace.reference is not None:
            run.offset = trace.final_position - full_end
            run.reference = {
                "kind": trace.reference["kind"],
                "position": trace.reference["position"],
                "value": trace.reference["value"],
                "time": leg.ref_time,
            }
            run.ends_moving = trace.ends_moving
            if run.outcome not in ("failed", "aborted"):
                run.outcome, run.failure = "homed", None
        elif run.outcome not in ("failed", "aborted"):
            if trace.outcome == "not_required":
                run.outcome = "homed"
                run.offset = 0.0 if run.offset is None else run.offset
            elif plan.axes[name].strategy.definition.skipped_by_g74:
                run.outcome = "skipped"
                if plan.axes[name].absolute and run.offset is None:
                    run.offset = 0.0  # the absolute encoder gives the position
            elif plan.axes[name].strategy.controlled_by == "drive" and trace.outcome == "skipped":
                run.outcome = "not_simulated"
            else:
                run.outcome, run.failure = trace.outcome, trace.failure
        for follower in leg.followers:
            self._follow(follower, leg, moved, homed, follower in homing)

    def _follow(self, name: str, leg: _Leg, moved: float, leader_homed: bool, homes_next: bool) -> None:
        """A gantry partner tracks the leader: the same phases and times, shifted to its own position."""
        run = self.result.axes[name]
        shift = self.x[name] - leg.x_start
        for phase in leg.phases:
            run.phases.append(
                AxisPhase(
                    f"with {leg.name}: {phase.name}",
                    "following",
                    phase.block,
                    phase.start_time,
                    phase.end_time,
                    phase.start_position + shift,
                    phase.end_position + shift,
                    phase.velocity,
                    phase.direction,
                    phase.ended_by,
                    [Segment(s.t0, s.t1, s.x0 + shift, s.v0, s.a) for s in phase.segments],
                )
            )
        at_reference = None
        if leg.ref_time is not None and leader_homed:
            at_reference = _position_at(leg.phases, leg.ref_time, leg.x_start) + shift
        self.x[name] += moved
        if leader_homed and at_reference is not None and self.plan.suppressed(name):
            value = self.plan.axes[name].reference_position
            run.offset = value - at_reference
            run.reference = {
                "kind": f"with its master {leg.name}",
                "position": at_reference,
                "value": value,
                "time": leg.ref_time,
            }
            if run.outcome not in ("failed", "aborted"):
                run.outcome, run.failure = "homed", None
        elif (
            leg.name == self.plan.master.get(name)
            and run.outcome == "not_commanded"
            and leg.phases
            and not homes_next  # its own homing runs next in this group
        ):
            run.warn(
                None,
                f"moved with its gantry master {leg.name}; its own homing (not suppressed, P-AXIS-00074) "
                "still has to run",
            )

    # -- G00 / G01 ---------------------------------------------------------------------------------
    def _move(self, index: int, block: MoveBlock, t: float) -> float:
        plan, axes = self.plan, self.result.axes
        targets: dict[str, float] = {}
        for word in block.targets:
            name = word.name.upper()
            if not self._known(index, word, t, f"the block moves {name}"):
                return t
            if name in plan.uncoupled:
                self._fail(index, word.at, name, plan.uncoupled[name], t, "gantry coupling without a master")
                return t
            prepared = plan.axes[name]
            if prepared.spindle:
                self.result.warn(
                    None, f"{name} is a spindle: its word in a motion block is not simulated", word.at
                )
                continue
            if plan.suppressed(name) or name in plan.master:
                self.result.warn(
                    None,
                    f"{name} is a gantry slave: it moves with its master {plan.master[name]}; its own word is "
                    "not simulated",
                    word.at,
                )
                continue
            run = axes[name]
            x = self.x[name]
            if block.absolute and prepared.modulo:
                # where the word puts the axis, in the frame the word is read in (homed, or actual values)
                target = x + _short_way(word.value - (x + (run.offset or 0.0)), prepared.modulo)
            elif block.absolute:
                target = word.value - run.offset if run.offset is not None else word.value
            else:
                target = x + word.value
            if run.offset is not None and not prepared.modulo and not prepared.spindle:
                low, high = prepared.soft_limits
                value = target + run.offset
                if not low - 1e-9 <= value <= high + 1e-9:
                    self._fail(
                        index,
                        word.at,
                        name,
                        f"the target {name}{_num(value)} lies outside the software limits "
                        f"[{_num(low)}, {_num(high)}] {unit_label(prepared.unit)}: the CNC does not run the block",
                        t,
                        "target outside the software limits",
                    )
                    return t
            if run.offset is None:
                self.result.warn(
                    "LIS606",
                    f"{block_text(block)} moves {name} before it is homed: the positions are raw actual values "
                    "and the software limits are not monitored yet",
                    word.at,
                )
            targets[name] = target
        if not block.rapid and block.feed_mm_min is None and targets:
            self._fail(index, block.at, None, "G01 without a feed: program F (mm/min)", t, "no feed")
            return t
        deltas = {n: target - self.x[n] for n, target in targets.items() if abs(target - self.x[n]) > 1e-12}
        if not deltas:
            return t
        length = math.sqrt(sum(d * d for d in deltas.values()))
        speed = math.inf if block.rapid else (block.feed_mm_min or 0.0) / 60.0
        acceleration = math.inf
        for n, d in deltas.items():
            prepared, homed = plan.axes[n], axes[n].homed
            share = abs(d) / length
            limit = prepared.speed_limit(homed)
            if block.rapid:
                limit = min(limit, prepared.rapid)
            speed = min(speed, limit / share)
            acceleration = min(acceleration, prepared.move_acceleration / share)
        if speed <= 0:
            self._fail(index, block.at, None, "the feed is 0: the axes do not move", t, "no feed")
            return t
        peak, t_acc, cruise = trapezoid(length, speed, acceleration)
        duration = 2 * t_acc + cruise
        # A hardware limit switch (scenario) on the way stops the move: all axes brake.
        stop: tuple[float, str] | None = None
        for n, d in deltas.items():
            switches = self._switches(n)
            if switches is None or plan.axes[n].modulo:
                continue
            room = (switches[1] - self.x[n]) if d > 0 else (self.x[n] - switches[0])
            if 0 <= room < abs(d):
                when = t + _time_at(room / abs(d) * length, length, peak, t_acc, cruise, acceleration)
                if stop is None or when < stop[0]:
                    stop = (when, n)
        moved: dict[str, list[AxisPhase]] = {}
        text = block_text(block)
        for n, d in deltas.items():
            u = d / length
            x0 = self.x[n]
            segments = [Segment(t, t + t_acc, x0, 0.0, u * acceleration)]
            x1 = x0 + u * peak * t_acc / 2
            if cruise > 0:
                segments.append(Segment(t + t_acc, t + t_acc + cruise, x1, u * peak, 0.0))
            x2 = x1 + u * peak * cruise
            segments.append(Segment(t + t_acc + cruise, t + duration, x2, u * peak, -u * acceleration))
            moved[n] = [
                AxisPhase(
                    text,
                    "move",
                    index,
                    t,
                    t + duration,
                    x0,
                    x0 + d,
                    abs(u) * peak,
                    _dir(d),
                    "target reached",
                    segments,
                )
            ]
        end = t + duration
        if stop is not None:
            when, hit = stop
            # Unhomed, no software limit guards the axis; homed, the switch lies inside its software limits.
            why = (
                "it is homed, and this limit switch lies inside its software limits"
                if axes[hit].homed
                else "it is not homed, so no software limit stops it first"
            )
            self._fail(
                index,
                block.at,
                hit,
                f"{hit} reaches its limit switch during {text} ({why})",
                when,
                "limit switch reached during a move",
            )
            end = when
            for n, phases in moved.items():
                _cut(phases, when, plan.axes[n].move_acceleration, "stopped: limit switch")
                if phases:
                    end = max(end, phases[-1].end_time)
        for n, phases in moved.items():
            axes[n].phases.extend(phases)
            shift_by = phases[-1].end_position - self.x[n] if phases else 0.0
            for partner in plan.partners(n):
                if partner in deltas:
                    continue
                offset = self.x[partner] - self.x[n]
                for phase in phases:
                    axes[partner].phases.append(
                        AxisPhase(
                            f"with {n}: {phase.name}",
                            "following",
                            index,
                            phase.start_time,
                            phase.end_time,
                            phase.start_position + offset,
                            phase.end_position + offset,
                            phase.velocity,
                            phase.direction,
                            phase.ended_by,
                            [Segment(s.t0, s.t1, s.x0 + offset, s.v0, s.a) for s in phase.segments],
                        )
                    )
                self.x[partner] += shift_by
            self.x[n] += shift_by
        return end


def _kind(block: HomingBlock | MoveBlock | SkippedBlock) -> str:
    return (
        "homing" if isinstance(block, HomingBlock) else "move" if isinstance(block, MoveBlock) else "skipped"
    )


def _names(block: HomingBlock | MoveBlock | SkippedBlock) -> list[str]:
    if isinstance(block, HomingBlock):
        return [w.name.upper() for w in block.words]
    if isinstance(block, MoveBlock):
        return [w.name.upper() for w in block.targets]
    return [w.name.upper() for w in block.homes + block.moves]


# --- sweeps -------------------------------------------------------------------------------------


def start_range(scenario: Scenario) -> tuple[float, float]:
    """Where sweep start positions are drawn for an axis: between its limit switches, over one revolution
    on a modulo axis without them, else 100 either side of its start."""
    if scenario.limit_switches is not None:
        return scenario.limit_switches
    if scenario.modulo is not None:
        return scenario.modulo
    return scenario.start_position - 100.0, scenario.start_position + 100.0


def sweep(plan: MachinePlan, runs: int, seed: int = 1) -> dict[str, Any]:
    """Run the program from `runs` random start positions (every axis drawn from its own range, a gantry
    slave kept at its scenario distance from its master) and cam jitters; report the spread of the total
    time and which axis fails how often, and why."""
    rng = random.Random(seed)
    # A gantry slave is bolted to its master: it starts at the scenario's distance from wherever the master
    # starts (drawn on its own, the two could start a metre apart, which no gantry can).
    apart = {
        slave: plan.axes[slave].scenario.start_position - plan.axes[master].scenario.start_position
        for slave, master in plan.master.items()
        if slave in plan.axes and master in plan.axes and master not in plan.master
    }
    drawn = {
        name: start_range(prepared.scenario) for name, prepared in plan.axes.items() if name not in apart
    }
    ranges: dict[str, tuple[float, float]] = {}
    for name in plan.axes:
        low, high = drawn[plan.master[name]] if name in apart else drawn[name]
        gap = apart.get(name, 0.0)
        ranges[name] = (low + gap, high + gap)
    jitters = {name: prepared.scenario.cam_jitter for name, prepared in plan.axes.items()}
    times: list[float] = []
    failures: Counter[tuple[str, str]] = Counter()
    for _ in range(runs):
        starts = {name: rng.uniform(low, high) for name, (low, high) in drawn.items()}
        starts.update({slave: starts[plan.master[slave]] + gap for slave, gap in apart.items()})
        shifts = {name: rng.uniform(-j, j) for name, j in jitters.items() if j}
        result = plan.run(starts, shifts)
        if result.failure is None:
            times.append(result.total_time)
        else:
            failures[(result.failure.axis or "(program)", result.failure.cause)] += 1
    by_axis: dict[str, dict[str, Any]] = {}
    for (axis, cause), count in failures.most_common():
        entry = by_axis.setdefault(axis, {"axis": axis, "failed": 0, "reasons": []})
        entry["failed"] += count
        entry["reasons"].append({"reason": cause, "count": count})
    homed = {w.name.upper() for b in plan.program.blocks if isinstance(b, HomingBlock) for w in b.words}
    geometry = ("cam", "zero_pulse_period", "zero_pulse_phase", "limit_switches")
    assumed = {
        name: [g for g in geometry if g in prepared.scenario.assumed]
        for name, prepared in plan.axes.items()
        if name in homed and prepared.strategy.moves
    }
    summary: dict[str, Any] = {
        "runs": runs,
        "completed": len(times),
        "failed": runs - len(times),
        "start_ranges": {name: [round(low, 9), round(high, 9)] for name, (low, high) in ranges.items()},
        "failures": sorted(by_axis.values(), key=lambda e: -e["failed"]),
        "assumed_geometry": {name: found for name, found in assumed.items() if found},
    }
    if times:
        summary["total_time"] = {
            "min": round(min(times), 9),
            "median": round(statistics.median(times), 9),
            "max": round(max(times), 9),
            "spread": round(max(times) - min(times), 9),
        }
    return summary

"""The motion of one axis while it homes, computed analytically, segment by segment; the sequences in
`homing/sequences/` drive it.

Every move starts from rest, accelerates with constant acceleration to its
speed, may cruise, and brakes with the same acceleration once the event that
ends it was detected. Positions of events follow from the motion equations in
closed form (no time-stepping loop); a signal without hardware latch is seen at
the next CNC cycle (error at most v·T), a latched zero pulse exactly. After the
reference event the axis brakes, so it stands beyond the reference by the
braking distance v²/2a (TF5200 homing manual §2: "Axis position after homing"),
except in flying spindle homing (§2.3.2.1), where the spindle keeps turning and
the trace ends at the reference event, still moving.

On spindles and modulo rotary axes the cam and the zero pulses recur every
revolution (`getriebe[i].modulou..moduloo`); trace positions keep counting
past the range, the reference and final positions are wrapped into it.

Units: mm (degrees for rotary axes and spindles) and seconds. Positions in the
trace are in the scenario's frame (the actual values before homing);
`final_position` is in the homed frame, where the reference event gets the
value `pos_refpkt` (or `torq_homing_position`).

The trace records what it found as facts (`SoftLimitOvershoot`, `StartOnCam`,
`PulseMargin`); the rules they belong to (LIS317, LIS402, LIS405) put them in
words. The simulator reads the strategy through `Homing`, the part of
`homing.base.HomingStrategy` it needs.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Protocol, TypedDict

from ..catalogue.units import unit_label
from .setup import POSITION, VELOCITY

if TYPE_CHECKING:
    from ..axis.resolved import ResolvedAxis
    from .scenario import Scenario
    from .setup import Acceleration, HomingSetup

INF = math.inf
ZERO_SEARCH_EXCEEDED = "zero_pulse_search_max_dist exceeded (maximum search distance)"
LIMIT_SWITCH = "limit switch reached"
PATH_LIMIT = "homing_max_movement_dist exceeded (P-ERR-70394)"
# The outcome of a run the simulator does not cover: not a failure of the homing (exit 0, with a note).
NOT_SIMULATED = "not_simulated"
__all__ = ["POSITION", "VELOCITY", "Simulator", "Trace"]

# Where the cam signal is active: is(x) active, and the distance from x in direction s to where it
# becomes active (`entry`) or stops being active (`exit`).
Active = Callable[[float], bool]
Crossing = Callable[[float, int], float]


class Homing(Protocol):
    """What the simulation reads of the strategy it runs (`homing.base.HomingStrategy` is one)."""

    @property
    def id(self) -> str: ...

    @property
    def title(self) -> str: ...

    @property
    def setup(self) -> HomingSetup: ...

    @property
    def gear(self) -> int: ...

    @property
    def direction(self) -> int: ...

    @property
    def acceleration(self) -> Acceleration | None: ...

    @property
    def with_cam(self) -> bool: ...

    @property
    def with_zero_pulse(self) -> bool: ...

    @property
    def one_phase(self) -> bool: ...

    @property
    def retracts(self) -> bool: ...

    @property
    def flying(self) -> bool: ...

    @property
    def controlled_by(self) -> str: ...

    @property
    def moves(self) -> bool: ...

    @property
    def unlatched_zero_pulse(self) -> bool: ...

    def simulate(self, simulator: Simulator, trace: Trace, start: float, cam_shift: float) -> Trace: ...


@dataclass(slots=True)
class Segment:
    """A piece of motion with constant acceleration: x(t) = x0 + v0 (t - t0) + a (t - t0)² / 2."""

    t0: float
    t1: float
    x0: float
    v0: float
    a: float

    def position(self, t: float) -> float:
        dt = t - self.t0
        return self.x0 + self.v0 * dt + 0.5 * self.a * dt * dt

    def velocity(self, t: float) -> float:
        return self.v0 + self.a * (t - self.t0)


@dataclass
class PhaseRecord:
    name: str
    direction: str | None
    velocity: float  # commanded speed, mm/s or °/s
    start_position: float
    end_position: float
    start_time: float
    end_time: float
    ended_by: str
    segments: list[Segment] = field(default_factory=list)


@dataclass
class Event:
    time: float
    position: float
    kind: str


class ReferenceEvent(TypedDict):
    """The reference event: its kind, where it happened (scenario frame), the value set there (homed frame),
    the speed the axis had and when (seconds after the homing start)."""

    kind: str
    position: float
    value: float
    speed: float
    time: float


@dataclass(frozen=True)
class Arming:
    """Where the zero-pulse logic of §2.6 was armed in a run that references on a zero pulse (scenario frame,
    continuous): `cam` where the reference cam was operated (its edge as the CNC saw it; None without a cam,
    where the logic is armed when the search starts) and `armed` that point plus
    shift_offset_zero_pulse_activation (P-AXIS-00494)."""

    cam: float | None
    armed: float


class TraceWarning(TypedDict):
    code: str | None  # the rule a finding belongs to (LIS317, LIS402, LIS405), a P-ERR id, None for a note
    message: str


# -- facts the rules word ------------------------------------------------------------------------------


@dataclass(frozen=True)
class SoftLimitOvershoot:
    """The reference value, or where the axis stands once homing has ended, lies outside the software limits
    (LIS317). Positions in the homed frame."""

    value: float  # what the reference event sets (pos_refpkt or torq_homing_position)
    final: float  # where the axis stands once homing has ended
    limits: tuple[float, float]  # swe_neg, swe_pos
    unit: str
    retracted: bool  # it came to rest by retracting from a fixed stop (else by braking)

    @property
    def reference_outside(self) -> bool:
        low, high = self.limits
        return not low <= self.value <= high


@dataclass(frozen=True)
class StartOnCam:
    """One-phase homing with a cam starts on the cam, so it references without leaving it (LIS402)."""

    position: float


@dataclass(frozen=True)
class PulseMargin:
    """A zero pulse so close to the point where the zero-pulse logic is armed that the spread of that point can
    put it on either side (LIS405), with the shift that moves the pulse half a period away and what that shift
    does to the reference."""

    ahead: float  # from the arming point to the pulse the logic takes, along the homing direction
    behind: float  # from the pulse just before the arming point to it
    margin: float  # the arming point's spread: one cycle at the speed the cam is crossed, plus the cam jitter
    period: float  # one zero-pulse period (encoder revolution)
    wanted: float  # the shift_offset_zero_pulse_activation (unit) that puts the pulse half a period away
    periods: int  # whole pulse periods the reference moves with it (+: in the homing direction)
    moved: float  # how far the reference moves then (scenario frame; within ±half a revolution when modulo)
    reference_value: float  # the pos_refpkt (unit, homed frame) that keeps the axis's coordinates
    modulo: tuple[float, float] | None
    gear: int
    unit: str


Fact = SoftLimitOvershoot | StartOnCam | PulseMargin


@dataclass
class Trace:
    strategy: Homing
    scenario: Scenario
    unit: str  # "mm" or "deg"
    acceleration: float | None
    acceleration_source: str = ""
    phases: list[PhaseRecord] = field(default_factory=list)
    events: list[Event] = field(default_factory=list)
    reference: ReferenceEvent | None = None
    final_position: float | None = None  # homed frame
    outcome: str = "homed"
    failure: str | None = None
    warnings: list[TraceWarning] = field(default_factory=list)  # notes, and the facts once worded
    facts: list[Fact] = field(default_factory=list)  # in the order they were found
    ends_moving: bool = False  # flying spindle homing: the trace ends at the reference, still turning
    arming: Arming | None = None  # where the zero-pulse logic was armed (zero-pulse references only)
    searched: tuple[str, float] | None = (
        None  # a failed search: what it looked for and where (scenario frame)
    )
    reference_at: float | None = None  # the reference event's position, scenario frame, not wrapped

    @property
    def cam_zero_pulse_offset(self) -> float | None:
        """The distance from where the reference cam was operated to the zero pulse taken as the reference,
        along the homing direction: what the CNC object "reference cam - zero pulse offset" reads after homing
        (§2.6). It includes shift_offset_zero_pulse_activation; None without a cam or a zero-pulse reference."""
        if self.arming is None or self.arming.cam is None or self.reference_at is None:
            return None
        return abs(self.reference_at - self.arming.cam)

    @property
    def total_time(self) -> float:
        return self.phases[-1].end_time if self.phases else 0.0

    @property
    def total_distance(self) -> float:
        return sum(abs(p.end_position - p.start_position) for p in self.phases)

    def warn(self, code: str | None, message: str) -> None:
        self.warnings.append({"code": code, "message": message})


class NoMotion(Exception):
    """A move asked for at a speed or an acceleration that is not above 0: the axis cannot get anywhere."""

    def __init__(self, speed: float, acceleration: float) -> None:
        super().__init__(speed, acceleration)
        self.speed, self.acceleration = speed, acceleration


class Ramp:
    """A move from (t0, x0) in direction s that reaches speed v with acceleration a, until it is stopped.

    It starts from rest, or at the speed `v0` (≥ 0, along s) of a spindle turning endlessly (§2.3.2.1), which
    then accelerates or decelerates to v: during the first t_acc = |v - v0|/a the speed changes linearly and
    the axis covers d_acc = |v² - v0²|/2a."""

    __slots__ = ("a", "d_acc", "k", "s", "t0", "t_acc", "v", "v0", "x0")

    def __init__(self, t0: float, x0: float, s: int, v: float, a: float, v0: float = 0.0) -> None:
        if not (v > 0 and a > 0):  # also NaN
            raise NoMotion(v, a)
        self.t0, self.x0, self.s, self.v, self.a, self.v0 = t0, x0, s, v, a, v0
        self.k = 1.0 if v >= v0 else -1.0  # accelerating (+1) or decelerating (-1) to v
        self.t_acc = abs(v - v0) / a
        self.d_acc = abs(v * v - v0 * v0) / (2 * a)

    def time_to(self, distance: float) -> float:
        """Time after t0 at which the axis has travelled `distance` (≥ 0)."""
        if distance <= self.d_acc:
            if not self.v0:
                return math.sqrt(2 * distance / self.a)
            # v0·t + k·a·t²/2 = d, in the form that stays exact when the speed barely changes
            root = math.sqrt(max(self.v0 * self.v0 + 2 * self.k * self.a * distance, 0.0))
            return 2 * distance / (self.v0 + root)
        return self.t_acc + (distance - self.d_acc) / self.v

    def distance_at(self, t: float) -> float:
        if t <= self.t_acc:
            return self.v0 * t + 0.5 * self.k * self.a * t * t
        return self.d_acc + self.v * (t - self.t_acc)

    def speed_at(self, t: float) -> float:
        return self.v0 + self.k * self.a * min(t, self.t_acc)

    def _speed_change(self, t: float) -> list[Segment]:
        """The segment of the speed change up to t after the start (none when the move starts at v)."""
        if not self.t_acc:
            return []
        t0 = self.t0
        return [Segment(t0, t0 + min(t, self.t_acc), self.x0, self.s * self.v0, self.s * self.k * self.a)]

    def run_until(self, t: float) -> list[Segment]:
        """The segments up to t after the start, without braking (the axis is still moving then)."""
        t0, x0, s = self.t0, self.x0, self.s
        segments = self._speed_change(t)
        if t > self.t_acc:
            segments.append(Segment(t0 + self.t_acc, t0 + t, x0 + s * self.d_acc, s * self.v, 0.0))
        return segments

    def stop(self, t_brake: float) -> tuple[list[Segment], float, float]:
        """Brake from time t0 + t_brake; returns the segments, the end time and the end position."""
        s, a, t0, x0 = self.s, self.a, self.t0, self.x0
        segments = self._speed_change(t_brake)
        if t_brake > self.t_acc:
            segments.append(Segment(t0 + self.t_acc, t0 + t_brake, x0 + s * self.d_acc, s * self.v, 0.0))
        speed = self.speed_at(t_brake)
        x_brake = x0 + s * self.distance_at(t_brake)
        t_end = t0 + t_brake + speed / a
        segments.append(Segment(t0 + t_brake, t_end, x_brake, s * speed, -s * a))
        return segments, t_end, x_brake + s * speed * speed / (2 * a)


class Simulator:
    """Simulates one axis's configured homing in a scenario: the axis's values, where the signals are, and the
    moves the sequences are made of."""

    def __init__(self, values: ResolvedAxis, strategy: Homing, scenario: Scenario) -> None:
        # Every value comes from the strategy's homing setup: after the CNC's corrections, in mm and seconds.
        setup = strategy.setup
        self.values = values
        self.strategy = strategy
        self.scenario = scenario
        self.rotary = setup.rotary
        self.unit = setup.unit
        self.direction = strategy.direction
        self.acceleration, self.acceleration_source = _acceleration(strategy, scenario)
        self.fast = setup.fast
        self.slow = setup.slow
        self.fast_from_cam = setup.fast_from_cam
        self.cam_level = setup.cam_level
        self.shift = setup.shift
        self.zero_search_max = setup.zero_pulse_search_max
        self.total_max = setup.path_limit
        self.refpkt = setup.reference_position
        self.soft_limits = setup.soft_limits
        self.overflow = setup.overflow
        self.modulo = setup.modulo  # (low, high) in degrees when positions wrap, else None
        self.revolution = self.modulo[1] - self.modulo[0] if self.modulo else 0.0
        self.start = scenario.start_position  # path monitoring counts from here (set by run)

    @property
    def ramp_acceleration(self) -> float:
        """The acceleration of the moves. Only drive-controlled homing without a [drive] table has none, and
        that strategy stands still."""
        if self.acceleration is None:
            raise AssertionError("no acceleration for a move: the strategy does not move the axis")
        return self.acceleration

    def active_zone(self, lo: float, hi: float) -> tuple[Active, Crossing, Crossing]:
        """Membership and crossing distances of the region where the cam signal is active.

        On a modulo axis (spindle, rotary axis with MODULO) the cam recurs every revolution: the zone is
        [lo, hi] + k·revolution, so every crossing distance is finite."""
        inside_cam = self.cam_level
        if self.modulo:
            return self._active_modulo(lo, hi, inside_cam)

        def active(x: float) -> bool:
            return (lo <= x <= hi) == inside_cam

        def entry(x: float, s: int) -> float:
            if active(x):
                return 0.0
            if inside_cam:
                if s > 0:
                    return lo - x if x < lo else INF
                return x - hi if x > hi else INF
            return hi - x if s > 0 else x - lo

        def exit_(x: float, s: int) -> float:
            if not active(x):
                return 0.0
            if inside_cam:
                return hi - x if s > 0 else x - lo
            if x < lo:
                return lo - x if s > 0 else INF
            return x - hi if s < 0 else INF

        return active, entry, exit_

    def _active_modulo(self, lo: float, hi: float, inside_cam: bool) -> tuple[Active, Crossing, Crossing]:
        period, width = self.revolution, hi - lo

        def offset(x: float) -> float:  # where x lies past the cam's start, within one revolution
            return (x - lo) % period

        def active(x: float) -> bool:
            return (offset(x) <= width) == inside_cam

        def entry(x: float, s: int) -> float:
            if active(x):
                return 0.0
            r = offset(x)
            if inside_cam:  # outside the cam: to the next cam start (s > 0) or back to its end (s < 0)
                return period - r if s > 0 else r - width
            return width - r if s > 0 else r  # on the cam, the active region is outside it

        def exit_(x: float, s: int) -> float:
            if not active(x):
                return 0.0
            r = offset(x)
            if inside_cam:
                return width - r if s > 0 else r
            return period - r if s > 0 else r - width

        return active, entry, exit_

    HORIZON_REVOLUTIONS = 100  # a modulo axis without any bound gives up after this many revolutions

    def wrap(self, x: float) -> float:
        """A position of a modulo axis brought into its range [modulou, moduloo); others unchanged."""
        if not self.modulo:
            return x
        low = self.modulo[0]
        return low + (x - low) % self.revolution

    def bound(self, x: float, s: int, travelled: float = 0.0, extra: float = INF) -> tuple[float, str]:
        """The first limit in the way: limit switch, homing_max_movement_dist or a phase-specific maximum.

        homing_max_movement_dist bounds the displacement from the homing start position (§2.4.1: the reference
        must be found "within a distance from the homing start position"), not the path length travelled, so
        moving back and forth across the cam does not use it up."""
        switches = self.scenario.limit_switches
        bounds: list[tuple[float, str]] = []
        if switches is not None:
            switch = switches[1] - x if s > 0 else x - switches[0]
            bounds.append((max(switch, 0.0), LIMIT_SWITCH))
        if self.total_max > 0:
            room = self.total_max - s * (x - self.start)
            bounds.append((max(room, 0.0), PATH_LIMIT))
        if extra < INF:
            bounds.append((max(extra, 0.0), ZERO_SEARCH_EXCEEDED))
        if not bounds:
            span = self.revolution * self.HORIZON_REVOLUTIONS if self.modulo else 1e7
            turns = (
                f"{self.HORIZON_REVOLUTIONS} revolutions"
                if self.modulo
                else f"{span:g} {unit_label(self.unit)}"
            )
            bounds.append((span, f"nothing found within {turns} and nothing else bounds the search"))
        return min(bounds)

    def sample(self, ramp: Ramp, distance: float, latched: bool) -> float:
        """Time after the ramp's start at which an event `distance` ahead is detected."""
        t = ramp.time_to(distance)
        if latched:
            return t
        cycle = self.scenario.cycle_time
        absolute = ramp.t0 + t
        detected = math.ceil(absolute / cycle - 1e-9) * cycle
        return max(detected - ramp.t0, t)

    def move(
        self,
        trace: Trace,
        name: str,
        x: float,
        t: float,
        s: int,
        speed: float,
        distance: float,
        latched: bool,
        ended_by: str,
        travelled: float,
        search_max: float = INF,
        before_bound: float = 0.0,
        target: str = "the event",
    ) -> tuple[float, float, float | None]:
        """Move until `target` (an event `distance` ahead, detected at a cycle unless latched), then brake.

        Returns (end position, end time, detection position or None when a bound stopped the move).
        """
        ramp = Ramp(t, x, s, speed, self.ramp_acceleration)
        bound, reason = self.bound(x, s, travelled, search_max + before_bound if search_max < INF else INF)
        if distance > bound:
            segments, t_end, x_end = ramp.stop(ramp.time_to(bound))
            trace.phases.append(
                PhaseRecord(name, direction_word(s), speed, x, x_end, t, t_end, reason, segments)
            )
            self.stopped(trace, name, reason, s, target, x, distance)
            return x_end, t_end, None
        t_detect = self.sample(ramp, distance, latched)
        segments, t_end, x_end = ramp.stop(t_detect)
        x_detect = x + s * ramp.distance_at(t_detect)
        switch = self.switch_in_braking(x_detect, x_end, s)
        if switch is not None:
            # The event was seen, but the braking after it runs onto a hardware limit switch: the CNC stops
            # homing with an error there, whatever was found (§2.3.1.1 and Fig. 1).
            trace.phases.append(
                PhaseRecord(name, direction_word(s), speed, x, x_end, t, t_end, LIMIT_SWITCH, segments)
            )
            trace.outcome = "failed"
            unit = unit_label(self.unit)
            trace.failure = (
                f"{name}: {ended_by} at {number(x_detect)} {unit}, then the limit switch at {number(switch)} "
                f"{unit} was reached while braking (braking distance {number(abs(x_end - x_detect))} {unit})"
            )
            return x_end, t_end, None
        trace.phases.append(
            PhaseRecord(name, direction_word(s), speed, x, x_end, t, t_end, ended_by, segments)
        )
        return x_end, t_end, x_detect

    def switch_in_braking(self, x_detect: float, x_end: float, s: int) -> float | None:
        """The limit switch that lies within the braking travel from x_detect to x_end (direction s), if any."""
        switches = self.scenario.limit_switches
        if switches is None:
            return None
        switch = switches[1] if s > 0 else switches[0]
        if s * (x_end - switch) > 1e-9 and s * (switch - x_detect) >= 0:
            return switch
        return None

    def edge_move(
        self,
        trace: Trace,
        name: str,
        x: float,
        t: float,
        s: int,
        speed: float,
        distance: float,
        ended_by: str,
        event: str,
        travelled: float,
        target: str = "the cam",
    ) -> tuple[float, float, bool]:
        """A sampled move to a cam edge that records the edge as an event; False when a bound stopped it."""
        x_end, t_end, x_edge = self.move(
            trace, name, x, t, s, speed, distance, False, ended_by, travelled, target=target
        )
        if x_edge is None:
            return x_end, t_end, False
        trace.events.append(Event(trace.phases[-1].segments[-1].t0, x_edge, event))
        return x_end, t_end, True

    def stopped(
        self,
        trace: Trace,
        name: str,
        reason: str,
        s: int,
        target: str,
        x: float,
        distance: float,
        when: str = "",
    ) -> None:
        """Homing failed: a bound (`reason`, from `bound`) stopped the move from x (`when`: while it did what)
        before `target`, which lay `distance` ahead (infinite: nowhere ahead). The failure names the bound with
        its value and the target with its position, and the trace keeps the target's position for the plot."""
        if math.isfinite(distance):
            where = x + s * distance
            trace.searched = (target, where)
            what = f"{target} at {number(where)} {unit_label(self.unit)}"
        else:
            what = f"{target}, which lies nowhere ahead in the {direction_word(s)} direction"
        trace.outcome, trace.failure = "failed", f"{name}: {self.why(reason, s)}{when} before {what}"

    def why(self, reason: str, s: int) -> str:
        """A bound that stopped a move, with its value: which limit switch, which parameter and how far."""
        unit = unit_label(self.unit)
        switches = self.scenario.limit_switches
        if reason == LIMIT_SWITCH and switches is not None:
            return f"the limit switch at {number(switches[1] if s > 0 else switches[0])} {unit} was reached"
        if reason == PATH_LIMIT:
            return (
                f"homing_max_movement_dist ({number(self.total_max)} {unit} from the start at "
                f"{number(self.start)} {unit}) was exceeded (P-ERR-70394)"
            )
        if reason == ZERO_SEARCH_EXCEEDED:
            return (
                f"zero_pulse_search_max_dist ({number(self.zero_search_max)} {unit} from where the zero-pulse "
                "logic was armed) was exceeded"
            )
        return reason

    def reference(
        self, trace: Trace, kind: str, position: float, time: float, value: float, x_end: float
    ) -> float:
        """Record the reference event at `time` and `position`; returns the position after homing (homed
        frame)."""
        trace.events.append(Event(time, position, kind))
        trace.reference_at = position
        speed = abs(trace.phases[-1].segments[-1].v0)  # the braking segment starts at the event
        trace.reference = {
            "kind": kind,
            "position": self.wrap(position),
            "value": value,
            "speed": speed,
            "time": time,
        }
        final = trace.final_position = self.wrap(value + (x_end - position))
        return final

    def run(self, start: float | None = None, cam_shift: float = 0.0) -> Trace:
        """Simulate from `start` (the scenario's start position by default); the strategy picks the sequence."""
        trace = Trace(self.strategy, self.scenario, self.unit, self.acceleration, self.acceleration_source)
        x = self.scenario.start_position if start is None else start
        self.start = x
        turning = self.scenario.start_velocity
        if self.strategy.unlatched_zero_pulse:
            return self.stand_still(
                trace,
                "failed",
                "the SERCOS drive's zero pulse is never captured: CNC-controlled homing on the zero pulse needs "
                "the drive's latch (antr.sercos.drive_supports_cnc_homing), the AX5000 latch "
                "(kenngr.echtzeit_bit_nr) or encoder-overflow homing, and none is configured (LIS322)",
            )
        try:
            if turning and self.strategy.moves and not self.strategy.flying:
                return self._from_rotation(trace, turning)
            return self.strategy.simulate(self, trace, x, cam_shift)
        except NoMotion as stuck:
            unit = f"{unit_label(self.unit)}/s"
            return self.stand_still(
                trace,
                "failed",
                f"the axis cannot move: a homing move at {stuck.speed:g} {unit} with an acceleration of "
                f"{stuck.acceleration:g} {unit}² never gets anywhere (homing speeds and acceleration "
                "must be above 0)",
            )

    def _from_rotation(self, trace: Trace, turning: float) -> Trace:
        """A spindle turning endlessly whose homing is not flying homing (§2.3.2: from endless rotation homing
        "can only be executed if ref_ohne_rev is set to TRUE. Otherwise, an error message is output"; LIS320).
        Drive-controlled homing from rotation is the drive's affair and not simulated."""
        speed = f"{turning:g} {unit_label(self.unit)}/s"
        if self.strategy.controlled_by != "cnc":
            return self.stand_still(
                trace,
                NOT_SIMULATED,
                note=f"{self.strategy.title} of a spindle turning at {speed} is not simulated: the drive "
                "runs its own sequence from rotation",
            )
        return self.stand_still(
            trace,
            "failed",
            f"the spindle turns endlessly at {speed}, and from endless rotation the CNC homes only without "
            "reversal (ref_ohne_rev 1, flying homing, §2.3.2); it reports an error and goes to the error "
            f"state instead of running {self.strategy.title} (LIS320)",
        )

    def check_soft_limits(self, trace: Trace) -> SoftLimitOvershoot | None:
        """The reference value or the position after homing outside the software limits (not on spindles, whose
        positions wrap): recorded as a fact of the trace, and returned."""
        if self.strategy.setup.spindle or trace.reference is None or trace.final_position is None:
            return None
        low, high = self.soft_limits
        value, final = trace.reference["value"], trace.final_position
        if low <= value <= high and low <= final <= high:
            return None
        fact = SoftLimitOvershoot(value, final, (low, high), self.unit, self.strategy.retracts)
        trace.facts.append(fact)
        return fact

    def stand_still(
        self, trace: Trace, outcome: str, failure: str | None = None, note: str | None = None
    ) -> Trace:
        """No homing move: the axis needs none, is skipped, or cannot be homed."""
        trace.outcome, trace.failure = outcome, failure
        if note:
            trace.warn(None, note)
        return trace

    def next_pulse(self, x: float, s: int) -> float:
        """Distance from x (in direction s) to the next zero pulse (or encoder overflow)."""
        period, phase = self.pulse_lattice()
        k = (x - phase) / period
        n = math.ceil(k - 1e-12) if s > 0 else math.floor(k + 1e-12)
        return abs(phase + n * period - x)

    def pulse_lattice(self) -> tuple[float, float]:
        period, phase = self.scenario.zero_pulse_period, self.scenario.zero_pulse_phase
        if self.overflow:
            setup = self.strategy.setup
            if setup.overflow_period:
                period = setup.overflow_period
            phase += setup.overflow_offset
        return period, phase

    @staticmethod
    def passing_time(trace: Trace, position: float, s: int, after: float) -> float | None:
        """When the axis, moving in direction s from time `after` on, first reaches `position`; None if never.

        Solves x(t) = position segment by segment: with u = s·v0, b = s·a and the gap g = s·(position - x0),
        b/2·τ² + u·τ = g gives τ = 2g / (u + sqrt(u² + 2bg)), the form that stays exact for b = 0."""
        for phase in trace.phases:
            for segment in phase.segments:
                if segment.t1 < after:
                    continue
                t0 = max(segment.t0, after)
                gap = s * (position - segment.position(t0))
                if gap <= 0:
                    return t0
                u, b, span = s * segment.velocity(t0), s * segment.a, segment.t1 - t0
                if u * span + 0.5 * b * span * span < gap - 1e-12:
                    continue
                root = math.sqrt(max(u * u + 2 * b * gap, 0.0))
                return t0 + min(2 * gap / (u + root), span)
        return None


def point_to_point(
    trace: Trace,
    name: str,
    x: float,
    t: float,
    s: int,
    speed: float,
    a: float,
    distance: float,
    ended_by: str = "retraction distance travelled",
) -> tuple[float, float]:
    """A move of a known length from rest to rest (triangular when too short to reach the speed)."""
    if distance <= 0:
        return x, t
    peak, t_acc, cruise = trapezoid(distance, speed, a)
    segments = [Segment(t, t + t_acc, x, 0.0, s * a)]
    x1 = x + s * peak * peak / (2 * a)
    if cruise > 0:
        segments.append(Segment(t + t_acc, t + t_acc + cruise, x1, s * peak, 0.0))
    t2 = t + t_acc + cruise
    x2 = x1 + s * peak * cruise
    segments.append(Segment(t2, t2 + t_acc, x2, s * peak, -s * a))
    x_end = x + s * distance
    trace.phases.append(
        PhaseRecord(name, direction_word(s), speed, x, x_end, t, t2 + t_acc, ended_by, segments)
    )
    return x_end, t2 + t_acc


def trapezoid(length: float, speed: float, acceleration: float) -> tuple[float, float, float]:
    """(peak speed, acceleration time, cruise time) of a rest-to-rest move over `length` that accelerates and
    brakes with `acceleration` (triangular when too short to reach `speed`)."""
    peak = min(speed, math.sqrt(length * acceleration))
    t_acc = peak / acceleration
    cruise = max((length - peak * peak / acceleration) / peak, 0.0) if peak else 0.0
    return peak, t_acc, cruise


def number(value: float) -> str:
    """A position or distance in a message: up to four decimals, without trailing zeros."""
    text = f"{value:.4f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


def direction_word(s: int) -> str:
    return "positive" if s > 0 else "negative"


def _acceleration(strategy: Homing, scenario: Scenario) -> tuple[float | None, str]:
    """The acceleration the strategy's moves use, and where it comes from (shown in the header and JSON); none
    for an axis that makes no homing move (absolute, DISABLED, IGNORE_ABS_POS, a gantry slave, NONE)."""
    if not strategy.moves and strategy.controlled_by != "drive":
        return None, "none: the axis makes no homing move"
    acceleration = strategy.acceleration
    if acceleration is not None:
        return acceleration.ramp, acceleration.words
    drive = scenario.drive
    if drive is None:
        return None, "the drive's own (not simulated without a [drive] table)"
    return drive.acceleration, "the drive's ([drive] acceleration of the scenario)"

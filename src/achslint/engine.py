"""The dry-run engine: homing simulated analytically, segment by segment.

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
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, TypedDict

from .homing import POSITION, VELOCITY, HomingStrategy
from .resolved import ResolvedAxis
from .scenario import Scenario

if TYPE_CHECKING:
    from .scenario_input import DriveInput, SearchInput

INF = math.inf
ZERO_SEARCH_EXCEEDED = "zero_pulse_search_max_dist exceeded (maximum search distance)"
__all__ = ["POSITION", "VELOCITY", "Simulator", "Trace"]

# Where the cam signal is active: is(x) active, and the distance from x in direction s to where it
# becomes active (`entry`) or stops being active (`exit`).
Active = Callable[[float], bool]
Crossing = Callable[[float, int], float]
# A drive search's trigger: the distance from x in direction s to its next edge (active at the start or not).
TriggerEdge = Callable[[float, int, bool], float]


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
    """The reference event: its kind, where it happened (scenario frame), the value set there (homed frame)
    and the speed the axis had."""

    kind: str
    position: float
    value: float
    speed: float


class TraceWarning(TypedDict):
    code: str | None  # the rule the finding belongs to (LIS317, LIS402, LIS405), None for a note
    message: str


@dataclass
class Trace:
    strategy: HomingStrategy
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
    warnings: list[TraceWarning] = field(default_factory=list)
    ends_moving: bool = False  # flying spindle homing: the trace ends at the reference, still turning

    @property
    def total_time(self) -> float:
        return self.phases[-1].end_time if self.phases else 0.0

    @property
    def total_distance(self) -> float:
        return sum(abs(p.end_position - p.start_position) for p in self.phases)

    def warn(self, code: str | None, message: str) -> None:
        self.warnings.append({"code": code, "message": message})


class _Ramp:
    """A move from rest at (t0, x0) in direction s with speed v and acceleration a, until it is stopped."""

    __slots__ = ("a", "d_acc", "s", "t0", "t_acc", "v", "x0")

    def __init__(self, t0: float, x0: float, s: int, v: float, a: float) -> None:
        self.t0, self.x0, self.s, self.v, self.a = t0, x0, s, v, a
        self.t_acc = v / a
        self.d_acc = v * v / (2 * a)

    def time_to(self, distance: float) -> float:
        """Time after t0 at which the axis has travelled `distance` (≥ 0)."""
        if distance <= self.d_acc:
            return math.sqrt(2 * distance / self.a)
        return self.t_acc + (distance - self.d_acc) / self.v

    def distance_at(self, t: float) -> float:
        if t <= self.t_acc:
            return 0.5 * self.a * t * t
        return self.d_acc + self.v * (t - self.t_acc)

    def speed_at(self, t: float) -> float:
        return min(self.a * t, self.v)

    def run_until(self, t: float) -> list[Segment]:
        """The segments up to t after the start, without braking (the axis is still moving then)."""
        t0, x0, s, a = self.t0, self.x0, self.s, self.a
        segments = [Segment(t0, t0 + min(t, self.t_acc), x0, 0.0, s * a)]
        if t > self.t_acc:
            segments.append(Segment(t0 + self.t_acc, t0 + t, x0 + s * self.d_acc, s * self.v, 0.0))
        return segments

    def stop(self, t_brake: float) -> tuple[list[Segment], float, float]:
        """Brake from time t0 + t_brake; returns the segments, the end time and the end position."""
        s, a, t0, x0 = self.s, self.a, self.t0, self.x0
        segments: list[Segment] = []
        accel_end = min(t_brake, self.t_acc)
        segments.append(Segment(t0, t0 + accel_end, x0, 0.0, s * a))
        if t_brake > self.t_acc:
            segments.append(Segment(t0 + self.t_acc, t0 + t_brake, x0 + s * self.d_acc, s * self.v, 0.0))
        speed = self.speed_at(t_brake)
        x_brake = x0 + s * self.distance_at(t_brake)
        t_end = t0 + t_brake + speed / a
        segments.append(Segment(t0 + t_brake, t_end, x_brake, s * speed, -s * a))
        return segments, t_end, x_brake + s * speed * speed / (2 * a)


class Simulator:
    """Simulates one axis's configured homing in a scenario."""

    def __init__(self, values: ResolvedAxis, strategy: HomingStrategy, scenario: Scenario) -> None:
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

    # -- helpers -----------------------------------------------------------------------------
    def _active(self, lo: float, hi: float) -> tuple[Active, Crossing, Crossing]:
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

    def wrap(self, x: float) -> float:
        """A position of a modulo axis brought into its range [modulou, moduloo); others unchanged."""
        if not self.modulo:
            return x
        low = self.modulo[0]
        return low + (x - low) % self.revolution

    HORIZON_REVOLUTIONS = 100  # a modulo axis without any bound gives up after this many revolutions

    def _bound(self, x: float, s: int, travelled: float = 0.0, extra: float = INF) -> tuple[float, str]:
        """The first limit in the way: limit switch, homing_max_movement_dist or a phase-specific maximum.

        homing_max_movement_dist bounds the displacement from the homing start position (§2.4.1: the reference
        must be found "within a distance from the homing start position"), not the path length travelled, so
        moving back and forth across the cam does not use it up."""
        switches = self.scenario.limit_switches
        bounds: list[tuple[float, str]] = []
        if switches is not None:
            switch = switches[1] - x if s > 0 else x - switches[0]
            bounds.append((max(switch, 0.0), "limit switch reached"))
        if self.total_max > 0:
            room = self.total_max - s * (x - self.start)
            bounds.append((max(room, 0.0), "homing_max_movement_dist exceeded (P-ERR-70394)"))
        if extra < INF:
            bounds.append((max(extra, 0.0), ZERO_SEARCH_EXCEEDED))
        if not bounds:
            span = self.revolution * self.HORIZON_REVOLUTIONS if self.modulo else 1e7
            turns = f"{self.HORIZON_REVOLUTIONS} revolutions" if self.modulo else f"{span:g} {self.unit}"
            bounds.append((span, f"nothing found within {turns} and nothing else bounds the search"))
        return min(bounds)

    def _sample(self, ramp: _Ramp, distance: float, latched: bool) -> float:
        """Time after the ramp's start at which an event `distance` ahead is detected."""
        t = ramp.time_to(distance)
        if latched:
            return t
        cycle = self.scenario.cycle_time
        absolute = ramp.t0 + t
        detected = math.ceil(absolute / cycle - 1e-9) * cycle
        return max(detected - ramp.t0, t)

    def _move(
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
    ) -> tuple[float, float, float | None]:
        """Move until an event `distance` ahead (detected at a cycle unless latched), then brake.

        Returns (end position, end time, detection position or None when a bound stopped the move).
        """
        ramp = _Ramp(t, x, s, speed, self.ramp_acceleration)
        bound, reason = self._bound(x, s, travelled, search_max + before_bound if search_max < INF else INF)
        if distance > bound:
            segments, t_end, x_end = ramp.stop(ramp.time_to(bound))
            trace.phases.append(PhaseRecord(name, _dir(s), speed, x, x_end, t, t_end, reason, segments))
            trace.outcome, trace.failure = "failed", f"{name}: {reason} before the event was found"
            return x_end, t_end, None
        t_detect = self._sample(ramp, distance, latched)
        segments, t_end, x_end = ramp.stop(t_detect)
        x_detect = x + s * ramp.distance_at(t_detect)
        trace.phases.append(PhaseRecord(name, _dir(s), speed, x, x_end, t, t_end, ended_by, segments))
        return x_end, t_end, x_detect

    def _edge_move(
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
    ) -> tuple[float, float, bool]:
        """A sampled move to a cam edge that records the edge as an event; False when a bound stopped it."""
        x_end, t_end, x_edge = self._move(trace, name, x, t, s, speed, distance, False, ended_by, travelled)
        if x_edge is None:
            return x_end, t_end, False
        trace.events.append(Event(trace.phases[-1].segments[-1].t0, x_edge, event))
        return x_end, t_end, True

    def _reference(
        self, trace: Trace, kind: str, position: float, time: float, value: float, x_end: float
    ) -> float:
        """Record the reference event; returns the position after homing (homed frame)."""
        trace.events.append(Event(time, position, kind))
        speed = abs(trace.phases[-1].segments[-1].v0)  # the braking segment starts at the event
        trace.reference = {"kind": kind, "position": self.wrap(position), "value": value, "speed": speed}
        final = trace.final_position = self.wrap(value + (x_end - position))
        return final

    # -- strategies --------------------------------------------------------------------------
    def run(self, start: float | None = None, cam_shift: float = 0.0) -> Trace:
        """Simulate from `start` (the scenario's start position by default); the strategy picks the sequence."""
        trace = Trace(self.strategy, self.scenario, self.unit, self.acceleration, self.acceleration_source)
        x = self.scenario.start_position if start is None else start
        self.start = x
        return self.strategy.definition.simulate(self, trace, x, cam_shift)

    def check_soft_limits(self, trace: Trace) -> None:
        """LIS317: the reference value or the position after homing outside the software limits (not on spindles)."""
        if self.strategy.setup.spindle or trace.reference is None or trace.final_position is None:
            return
        low, high = self.soft_limits
        unit = self.unit
        value, final = trace.reference["value"], trace.final_position
        if not low <= value <= high:
            trace.warn(
                "LIS317",
                f"the reference value {value:g} {unit} lies outside the software limits "
                f"[{low:g}, {high:g}] {unit}",
            )
        elif not low <= final <= high:
            what = "after retracting from the stop" if self.strategy.definition.retracts else "after braking"
            trace.warn(
                "LIS317",
                f"{what} the axis stands at {final:.6g} {unit}, outside the software limits "
                f"[{low:g}, {high:g}] {unit}: move the reference position inside by at least "
                f"{abs(final - value):.4g} {unit}",
            )

    # -- the sequences the strategies choose from ---------------------------------------------
    def stand_still(
        self, trace: Trace, outcome: str, failure: str | None = None, note: str | None = None
    ) -> Trace:
        """No homing move: the axis needs none, is skipped, or cannot be homed."""
        trace.outcome, trace.failure = outcome, failure
        if note:
            trace.warn(None, note)
        return trace

    def adopt(self, trace: Trace, x: float) -> Trace:
        """Compatibility mode NONE: pos_refpkt becomes the axis position where it stands."""
        trace.outcome = "homed"
        trace.reference = {"kind": "adopted", "position": x, "value": self.refpkt, "speed": 0.0}
        trace.final_position = self.refpkt
        return trace

    def drive_sequence(self, trace: Trace, x: float, cam_shift: float) -> Trace:
        """Drive-controlled homing: simulated when the scenario describes the drive's method."""
        if self.scenario.drive is None:
            return self.stand_still(
                trace,
                "skipped",
                note="drive-controlled homing: the drive runs its own sequence; "
                "describe its method in the scenario's [drive] table to simulate it",
            )
        return self._drive(trace, x, self.scenario.drive, cam_shift)

    def cam_sequence(self, trace: Trace, x: float, cam_shift: float) -> Trace:
        """The CNC-controlled sequences with a reference cam (one or three phases)."""
        if self.scenario.cam is None:
            return self.stand_still(
                trace, "failed", "the strategy needs a reference cam but the scenario has none"
            )
        lo, hi = self.scenario.cam
        return self._with_cam(trace, x, lo + cam_shift, hi + cam_shift)

    def _next_pulse(self, x: float, s: int) -> float:
        """Distance from x (in direction s) to the next zero pulse (or encoder overflow)."""
        period, phase = self._pulse_lattice()
        k = (x - phase) / period
        n = math.ceil(k - 1e-12) if s > 0 else math.floor(k + 1e-12)
        return abs(phase + n * period - x)

    def _pulse_lattice(self) -> tuple[float, float]:
        period, phase = self.scenario.zero_pulse_period, self.scenario.zero_pulse_phase
        if self.overflow:
            setup = self.strategy.setup
            if setup.overflow_period:
                period = setup.overflow_period
            phase += setup.overflow_offset
        return period, phase

    def _reference_search(
        self,
        trace: Trace,
        name: str,
        x: float,
        t: float,
        s: int,
        speed: float,
        cam_distance: float,
        travelled: float,
    ) -> Trace:
        """Move to the cam (or start the search on it) and reference on the cam edge or the next zero pulse."""
        scenario = self.scenario
        if not self.strategy.with_zero_pulse:
            x_end, _t_end, x_cam = self._move(
                trace,
                name,
                x,
                t,
                s,
                speed,
                cam_distance,
                False,
                "the cam edge was detected (sampled each cycle)",
                travelled,
            )
            if x_cam is not None:
                t_cam = trace.phases[-1].segments[-1].t0
                trace.events.append(Event(t_cam, x_cam, "cam edge detected"))
                self._reference(trace, "cam edge", x_cam, t_cam, self.refpkt, x_end)
            return trace
        if cam_distance > self._bound(x, s, travelled)[0]:
            # The cam is never reached: the move ends at a limit and homing fails.
            self._move(trace, name, x, t, s, speed, cam_distance, False, "", travelled)
            return trace
        # The cam edge is sampled; the zero-pulse logic starts `shift` later; the pulse itself may be latched.
        ramp = _Ramp(t, x, s, speed, self.ramp_acceleration)
        t_cam = self._sample(ramp, cam_distance, False)
        x_cam = x + s * ramp.distance_at(t_cam)
        activation = x_cam + s * self.shift
        pulse_distance = abs(activation - x) + self._next_pulse(activation, s)
        event = "encoder overflow" if self.overflow else "zero pulse"
        latched = scenario.hardware_latch or self.overflow
        self._check_pulse_margin(trace, activation, s, speed)
        # zero_pulse_search_max_dist counts from where the zero-pulse logic is armed (the cam edge plus the shift):
        # the manual does not say; this is the reading under which the shift cannot make a pulse unreachable.
        before = abs(activation - x) if self.zero_search_max > 0 else 0.0
        search_max = self.zero_search_max if self.zero_search_max > 0 else INF
        x_end, _t_end, x_ref = self._move(
            trace,
            name,
            x,
            t,
            s,
            speed,
            pulse_distance,
            latched,
            f"the {event} was detected" + ("" if latched else " (sampled each cycle)"),
            travelled,
            search_max,
            before,
        )
        if cam_distance <= abs(x_end - x) or x_ref is not None:
            self._arming_events(trace, "cam edge detected", t + t_cam, x_cam, s)
        if x_ref is not None:
            t_ref = trace.phases[-1].segments[-1].t0
            self._reference(trace, event, x_ref, t_ref, self.refpkt, x_end)
        return trace

    def _check_pulse_margin(self, trace: Trace, activation: float, s: int, speed: float) -> None:
        """LIS405: a zero pulse so close to the arming point that the cam's spread can put it on either side.

        The arming point moves with the cam edge: by the scenario's cam jitter and by the sampling of the edge,
        one cycle at the speed the cam is crossed (vb_reflow in three phases, vb_refmax in one phase). The
        message names the shift that puts the pulse half a revolution away, how far the reference moves with
        it (whole pulse periods) and the pos_refpkt that keeps the axis's coordinates."""
        period, _ = self._pulse_lattice()
        ahead = self._next_pulse(activation, s)  # the pulse the logic takes
        behind = period - ahead  # the pulse just before the arming point
        margin = speed * self.scenario.cycle_time + self.scenario.cam_jitter
        if ahead >= margin and behind >= margin:
            return
        unit = self.unit
        side = f"{ahead:.4g} {unit} after" if ahead < margin else f"{behind:.4g} {unit} before"
        wanted = (self.shift + ahead - period / 2) % period
        trace.warn(
            "LIS405",
            f"a zero pulse lies {side} the point where the zero-pulse logic is armed (one encoder revolution = "
            f"{period:g} {unit}); the cam jitter and the sampling of the cam edge ({margin:.4g} {unit}) can arm it "
            f"on either side, so the reference can jump by one revolution. Set "
            f"kenngr.shift_offset_zero_pulse_activation to about {round(wanted / POSITION)} (= {wanted:.4g} {unit}) "
            f"to put the pulse half a revolution away; {self._reference_moves(wanted, ahead, period, s)}",
        )

    def _reference_moves(self, wanted: float, ahead: float, period: float, s: int) -> str:
        """What the shift `wanted` does to the reference: the logic armed at (wanted - shift) further on takes
        the pulse half a period after it, so the reference moves by wanted - shift + period/2 - ahead along
        the homing direction, a whole number of pulse periods; pos_refpkt must move with it."""
        periods = round((wanted - self.shift + period / 2 - ahead) / period)
        moved = s * periods * period  # in the scenario frame
        if self.modulo:  # a whole revolution of a modulo axis is the same position
            half = self.revolution / 2
            moved = (moved + half) % self.revolution - half
        if not periods:
            return "the reference stays on the same zero pulse, so pos_refpkt keeps its value"
        if self.modulo and abs(moved) < 1e-9 * period:
            return (
                f"the reference moves by whole revolutions only, to the same position within "
                f"[{self.modulo[0]:g}, {self.modulo[1]:g}) {self.unit}, so pos_refpkt keeps its value"
            )
        unit = self.unit
        count = abs(periods)
        how_many = "one zero-pulse period" if count == 1 else f"{count} zero-pulse periods"
        way = "in" if periods > 0 else "against"
        value = self.wrap(self.refpkt + moved)
        return (
            f"the reference then moves {abs(moved):.6g} {unit} ({how_many}) {way} the homing direction: correct "
            f"getriebe[{self.strategy.gear}].pos_refpkt by {moved:+.6g} {unit}, to about "
            f"{round(value / POSITION)} (= {value:.6g} {unit}), so the axis keeps its coordinates"
        )

    def _with_cam(self, trace: Trace, x: float, lo: float, hi: float) -> Trace:
        s = self.direction
        active, entry, exit_ = self._active(lo, hi)
        t = 0.0
        if self.strategy.one_phase:
            return self._one_phase(trace, x, s, active, entry)
        fast = self.fast
        slow = self.slow
        travelled = 0.0
        if active(x):
            trace.events.append(Event(0.0, x, "on the cam at the start: phase 1 skipped"))
        else:
            x_end, t, reached = self._edge_move(
                trace,
                "to the reference cam",
                x,
                t,
                s,
                fast,
                entry(x, s),
                "the cam was reached (sampled each cycle)",
                "cam reached",
                travelled,
            )
            if not reached:
                return trace
            travelled += abs(x_end - x)
            x = x_end
            if not active(x):
                trace.outcome = "failed"
                trace.failure = (
                    f"the axis braked through the cam (braking distance "
                    f"{fast * fast / (2 * self.ramp_acceleration):.4g} {self.unit} is longer than the cam)"
                )
                return trace
        speed = fast if self.fast_from_cam else slow
        x_end, t, left = self._edge_move(
            trace,
            "off the reference cam",
            x,
            t,
            -s,
            speed,
            exit_(x, -s),
            "the cam was left (sampled each cycle)",
            "cam left",
            travelled,
        )
        if not left:
            return trace
        travelled += abs(x_end - x)
        x = x_end
        return self._reference_search(
            trace, "onto the cam and reference", x, t, s, slow, entry(x, s), travelled
        )

    def _one_phase(self, trace: Trace, x: float, s: int, active: Active, entry: Crossing) -> Trace:
        """Homing without reversal: flying spindle homing at vb_reflow; otherwise the cam is approached at
        vb_refmax and the reference is its edge (type I) or the next zero pulse, searched at vb_reflow (type III)."""
        if self.strategy.setup.spindle:
            return self._reference_search(
                trace, "reference on the fly", x, 0.0, s, self.slow, entry(x, s), 0.0
            )
        if active(x):
            trace.warn(
                "LIS402",
                "the axis starts on the reference cam: one-phase homing references without "
                "leaving it, at the wrong place",
            )
        if not self.strategy.with_zero_pulse:
            return self._reference_search(
                trace, "to the cam and reference", x, 0.0, s, self.fast, entry(x, s), 0.0
            )
        if active(x):  # on the cam already (LIS402): the logic is armed where the axis stands
            return self._reference_search(trace, "on to the reference", x, 0.0, s, self.slow, 0.0, 0.0)
        return self._one_phase_zero_pulse(trace, x, s, entry(x, s))

    def _one_phase_zero_pulse(self, trace: Trace, x: float, s: int, cam_distance: float) -> Trace:
        """One-phase homing on the cam and the zero pulse (§2.3.3.2) from a start off the cam.

        The cam is approached at vb_refmax and its edge sampled each cycle. The zero-pulse logic is armed at
        that point, or shift_offset_zero_pulse_activation further on (§2.6: enabled as soon as the cam is
        operated), whatever the axis does there: the first pulse after the arming point is the reference.
        After the cam the axis brakes to a stop; a pulse passed while braking ends homing there (the axis is
        already braking). Otherwise it searches on at vb_reflow, from where it stopped, and brakes after the
        pulse. zero_pulse_search_max_dist counts from the arming point."""
        x_stop, t_stop, reached = self._edge_move(
            trace,
            "to the reference cam",
            x,
            0.0,
            s,
            self.fast,
            cam_distance,
            "the cam was reached (sampled each cycle)",
            "cam reached" if self.shift else "cam reached, zero-pulse logic armed",
            0.0,
        )
        if not reached:
            return trace
        cam = trace.events[-1]
        armed = cam.position + s * self.shift
        pulse = armed + s * self._next_pulse(armed, s)
        event = "encoder overflow" if self.overflow else "zero pulse"
        latched = self.scenario.hardware_latch or self.overflow
        # The arming point inherits the cam's spread: its jitter and the sampling at the approach speed.
        self._check_pulse_margin(trace, armed, s, self.fast)
        search_max = self.zero_search_max if self.zero_search_max > 0 else INF
        found = s * (pulse - armed) <= search_max
        stop_at = pulse if found else armed + s * search_max  # where the search ends: pulse or search limit
        if s * (x_stop - stop_at) >= 0:  # passed while braking after the cam
            if self.shift:
                self._arming_events(trace, "", cam.time, cam.position, s)
            return self._end_while_braking(trace, stop_at, found, latched, event, s)
        x_end, _t_end, x_ref = self._move(
            trace,
            "on to the reference",
            x_stop,
            t_stop,
            s,
            self.slow,
            s * (pulse - x_stop),
            latched,
            f"the {event} was detected" + ("" if latched else " (sampled each cycle)"),
            abs(x_stop - x),
            search_max,
            s * (armed - x_stop),
        )
        if self.shift:
            self._arming_events(trace, "", cam.time, cam.position, s)
        if x_ref is not None:
            self._reference(trace, event, x_ref, trace.phases[-1].segments[-1].t0, self.refpkt, x_end)
        return trace

    def _end_while_braking(
        self, trace: Trace, point: float, found: bool, latched: bool, event: str, s: int
    ) -> Trace:
        """The search ends at `point` while the axis brakes after the cam: at the reference event (`found`) or
        at the search limit. The braking segment is split there, so the reference's speed is the speed then."""
        phase = trace.phases[-1]
        t_pass = self._passing_time(trace, point, s, phase.segments[-1].t0)
        if t_pass is None:  # pragma: no cover - the point lies within the braking travel
            raise AssertionError("a point within the braking travel is passed")
        if not found:
            phase.ended_by = ZERO_SEARCH_EXCEEDED
            trace.outcome = "failed"
            trace.failure = (
                f"{phase.name}: {ZERO_SEARCH_EXCEEDED} while braking after the cam, before the {event}"
            )
            return trace
        t_detect = t_pass
        if not latched:
            cycle = self.scenario.cycle_time
            t_detect = min(max(math.ceil(t_pass / cycle - 1e-9) * cycle, t_pass), phase.end_time)
        braking = phase.segments.pop()
        x_detect, v_detect = braking.position(t_detect), braking.velocity(t_detect)
        phase.segments += [
            Segment(braking.t0, t_detect, braking.x0, braking.v0, braking.a),
            Segment(t_detect, braking.t1, x_detect, v_detect, braking.a),
        ]
        phase.ended_by = f"{phase.ended_by}; the {event} was detected while braking"
        self._reference(trace, event, x_detect, t_detect, self.refpkt, phase.end_position)
        return trace

    @staticmethod
    def _passing_time(trace: Trace, position: float, s: int, after: float) -> float | None:
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

    def _arming_events(self, trace: Trace, cam_kind: str, t_cam: float, x_cam: float, s: int) -> None:
        """The events of the zero-pulse logic (§2.6): where the cam was operated and where the logic was armed.

        Without shift_offset_zero_pulse_activation both are one point (`cam_kind`, zero-pulse logic armed);
        with it the arming point follows the shift later, as its own event once the axis has passed it.
        An empty `cam_kind` adds only the arming event (the cam event is already in the trace)."""
        if not self.shift:
            trace.events.append(Event(t_cam, x_cam, f"{cam_kind}, zero-pulse logic armed"))
            return
        if cam_kind:
            trace.events.append(Event(t_cam, x_cam, cam_kind))
        armed = x_cam + s * self.shift
        t_armed = self._passing_time(trace, armed, s, t_cam)
        if t_armed is not None:
            kind = f"zero-pulse logic armed ({self.shift:g} {self.unit} after the cam edge, P-AXIS-00494)"
            trace.events.append(Event(t_armed, armed, kind))

    def flying(self, trace: Trace, x: float, cam_shift: float = 0.0) -> Trace:
        """Flying homing of a spindle (§2.3.2.1): no reversal and no stop.

        The spindle turns in the homing direction at vb_reflow with its default ramps. With a cam
        (ref_ohne_nocken 0) the cam counts where it changes from operated to not operated: a spindle off the
        cam turns onto it and through it, one on the cam turns until it leaves it; that edge (sampled each
        cycle) arms the zero-pulse logic, shift_offset_zero_pulse_activation later. Without a cam the logic
        is armed at once. The next zero pulse is the reference, and the spindle keeps turning at the speed it
        has: the trace ends at the reference event, moving."""
        s, speed = self.direction, self.slow
        scenario = self.scenario
        ramp = _Ramp(0.0, x, s, speed, self.ramp_acceleration)
        name = "reference on the fly"
        t_edge = None
        if self.strategy.with_cam:
            if scenario.cam is None:
                return self.stand_still(
                    trace, "failed", "flying homing with cam needs a reference cam but the scenario has none"
                )
            lo, hi = scenario.cam[0] + cam_shift, scenario.cam[1] + cam_shift
            active, entry, exit_ = self._active(lo, hi)
            if active(x):
                edge = exit_(x, s)
                trace.events.append(Event(0.0, x, "on the cam at the start: turns until the cam is left"))
            else:
                span = (hi - lo) if self.cam_level else (self.revolution or INF) - (hi - lo)
                edge = entry(x, s) + span
            bound, reason = self._bound(x, s)
            if edge > bound:
                return self._flying_abort(trace, ramp, name, bound, reason)
            t_edge = self._sample(ramp, edge, False)
            x_edge = x + s * ramp.distance_at(t_edge)
            activation = x_edge + s * self.shift
        else:
            activation = x
        event = "encoder overflow" if self.overflow else "zero pulse"
        latched = scenario.hardware_latch or self.overflow
        distance = abs(activation - x) + self._next_pulse(activation, s)
        extra = abs(activation - x) + self.zero_search_max if self.zero_search_max > 0 else INF
        bound, reason = self._bound(x, s, 0.0, extra)
        if distance > bound:
            return self._flying_abort(trace, ramp, name, bound, reason, t_edge, x)
        if t_edge is not None:
            self._check_pulse_margin(trace, activation, s, speed)
        t_ref = self._sample(ramp, distance, latched)
        x_ref = x + s * ramp.distance_at(t_ref)
        segments = ramp.run_until(t_ref)
        trace.phases.append(
            PhaseRecord(
                name,
                _dir(s),
                speed,
                x,
                x_ref,
                0.0,
                t_ref,
                f"the {event} was detected; the spindle turns on without stopping",
                segments,
            )
        )
        if t_edge is not None:
            self._edge_event(trace, t_edge, x + s * ramp.distance_at(t_edge))
        trace.events.append(Event(t_ref, x_ref, event))
        trace.reference = {
            "kind": event,
            "position": self.wrap(x_ref),
            "value": self.refpkt,
            "speed": ramp.speed_at(t_ref),
        }
        trace.final_position = self.wrap(self.refpkt)
        trace.ends_moving = True
        return trace

    def _edge_event(self, trace: Trace, t: float, position: float) -> None:
        self._arming_events(trace, "cam left", t, position, self.direction)

    def _flying_abort(
        self,
        trace: Trace,
        ramp: _Ramp,
        name: str,
        bound: float,
        reason: str,
        t_edge: float | None = None,
        x: float = 0.0,
    ) -> Trace:
        """A flying search that a bound ends: the CNC aborts homing and the spindle brakes."""
        segments, t_end, x_end = ramp.stop(ramp.time_to(bound))
        trace.phases.append(
            PhaseRecord(name, _dir(ramp.s), ramp.v, ramp.x0, x_end, ramp.t0, t_end, reason, segments)
        )
        if t_edge is not None and t_edge <= ramp.time_to(bound):
            self._edge_event(trace, t_edge, ramp.x0 + ramp.s * ramp.distance_at(t_edge))
        trace.outcome, trace.failure = "failed", f"{name}: {reason} before the event was found"
        return trace

    def zero_pulse_only(self, trace: Trace, x: float, cam_shift: float = 0.0) -> Trace:
        if not self.strategy.setup.zero_pulse:
            return self.stand_still(
                trace, "failed", "neither a reference cam nor a zero pulse marks the reference (LIS318)"
            )
        s = self.direction
        speed = self.slow
        event = "encoder overflow" if self.overflow else "zero pulse"
        latched = self.scenario.hardware_latch or self.overflow
        search_max = self.zero_search_max if self.zero_search_max > 0 else INF
        x_end, _t_end, x_ref = self._move(
            trace,
            f"to the {event}",
            x,
            0.0,
            s,
            speed,
            self._next_pulse(x, s),
            latched,
            f"the {event} was detected",
            0.0,
            search_max,
        )
        if x_ref is not None:
            self._reference(trace, event, x_ref, trace.phases[-1].segments[-1].t0, self.refpkt, x_end)
        return trace

    def simulated(self, trace: Trace, x: float, cam_shift: float = 0.0) -> Trace:
        s = self.direction
        speed = self.slow
        distance = abs(self.values.number("antr.simu.rpf_weg_bis_nip")) * POSITION
        x_end, _t_end, x_ref = self._move(
            trace,
            "to the simulated zero pulse",
            x,
            0.0,
            s,
            speed,
            distance,
            True,
            "the simulated zero pulse was reached",
            0.0,
        )
        if x_ref is not None:
            self._reference(
                trace, "simulated zero pulse", x_ref, trace.phases[-1].segments[-1].t0, self.refpkt, x_end
            )
        return trace

    def fixed_stop(self, trace: Trace, x: float, cam_shift: float = 0.0) -> Trace:
        values, gear = self.values, self.strategy.gear
        s = self.direction  # torq_homing_dir
        speed = values.number(f"getriebe[{gear}].homing.torq_move_velocity") * VELOCITY
        acceleration = values.number(f"getriebe[{gear}].homing.torq_move_acceleration")
        if speed <= 0 or acceleration <= 0:
            missing = "torq_move_velocity" if speed <= 0 else "torq_move_acceleration"
            trace.outcome, trace.failure = (
                "failed",
                f"{missing} is not set (0): the axis does not move (LIS315)",
            )
            return trace
        if self.strategy.setup.simulated:
            stop: float | None = x + s * values.number("kenngr.homing.torq_distance_to_block") * POSITION
        else:
            stop = self.scenario.fixed_stop
        reach = (stop - x) * s if stop is not None else 0.0
        min_distance = values.number("kenngr.homing.torq_min_distance") * POSITION
        max_distance = values.number("kenngr.homing.torq_max_distance") * POSITION
        ramp = _Ramp(0.0, x, s, speed, float(acceleration))
        if stop is None or reach <= 0 or (max_distance > 0 and reach > max_distance):
            limit = max_distance if max_distance > 0 else self._bound(x, s, 0.0)[0]
            segments, t_end, x_end = ramp.stop(ramp.time_to(limit))
            trace.phases.append(
                PhaseRecord(
                    "to the fixed stop",
                    _dir(s),
                    speed,
                    x,
                    x_end,
                    0.0,
                    t_end,
                    "torq_max_distance travelled without a stop",
                    segments,
                )
            )
            trace.outcome, trace.failure = "failed", "no fixed stop within torq_max_distance: homing aborted"
            return trace
        t_contact = ramp.time_to(reach)
        # At the stop the axis is blocked: the motion ends abruptly at the stop position.
        segments = ramp.stop(t_contact)[0][:-1]
        segments.append(Segment(t_contact, t_contact, stop, 0.0, 0.0))
        if reach < min_distance:
            trace.phases.append(
                PhaseRecord(
                    "to the fixed stop",
                    _dir(s),
                    speed,
                    x,
                    stop,
                    0.0,
                    t_contact,
                    "blocked before torq_min_distance",
                    segments,
                )
            )
            trace.outcome, trace.failure = (
                "failed",
                (
                    "the stop lies within torq_min_distance: detection is not armed "
                    "yet when the axis is blocked"
                ),
            )
            return trace
        detect = values.number("kenngr.homing.torq_detect_time") * 1e-6
        t_detect = t_contact + detect
        segments.append(Segment(t_contact, t_detect, stop, 0.0, 0.0))
        trace.phases.append(
            PhaseRecord(
                "to the fixed stop",
                _dir(s),
                speed,
                x,
                stop,
                0.0,
                t_detect,
                "the fixed stop was detected",
                segments,
            )
        )
        trace.events.append(Event(t_contact, stop, "fixed stop reached"))
        value = values.number("kenngr.homing.torq_homing_position") * POSITION
        retraction = values.number("kenngr.homing.torq_retraction_distance") * POSITION
        trace.events.append(Event(t_detect, stop, "fixed stop detected"))
        trace.reference = {"kind": "fixed stop", "position": stop, "value": value, "speed": 0.0}
        x_end, t_end = _point_to_point(
            trace, "retract from the stop", stop, t_detect, -s, speed, float(acceleration), retraction
        )
        trace.final_position = value + (x_end - stop)
        return trace

    # -- drive-side homing (Triamec drive homing methods) -------------------------------------
    EARLY_TRIGGER = 0.005  # s: a search whose trigger comes sooner is refused by the drive

    def _drive(self, trace: Trace, x: float, drive: DriveInput, cam_shift: float) -> Trace:
        values = self.values
        reference = drive.reference_position
        if reference is None:
            reference = self.refpkt if values.get("kenngr.write_reference_position_to_drive") else 0.0
        if drive.method == "immediate":
            trace.reference = {"kind": "immediate (no position set)", "position": x, "value": x, "speed": 0.0}
            trace.final_position = x
            return trace
        if drive.method == "at-position":
            trace.reference = {
                "kind": "position set at standstill",
                "position": x,
                "value": reference,
                "speed": 0.0,
            }
            trace.final_position = reference
            return trace
        if drive.method == "absolute-encoder":
            value = x + drive.encoder_offset
            trace.reference = {"kind": "absolute encoder offset", "position": x, "value": value, "speed": 0.0}
            trace.final_position = value
            return trace
        if drive.method == "nc":
            return self._nc_reference(trace, x, drive, reference, cam_shift)
        first_search, second_search = drive.first_search, drive.second_search
        if first_search is None or second_search is None:  # refused by DriveInput for the standard method
            raise AssertionError("the standard drive method needs a first and a second search")
        t = 0.0
        x, t, first = self._drive_search(trace, "first search", x, t, drive, first_search, cam_shift)
        if first is None:
            return trace
        if drive.relocate_distance:
            s = 1 if drive.relocate_distance > 0 else -1
            x, t = _point_to_point(
                trace,
                "relocate",
                x,
                t,
                s,
                drive.velocity,
                drive.acceleration,
                abs(drive.relocate_distance),
                "relocation distance travelled",
            )
        x_end, t, event = self._drive_search(trace, "second search", x, t, drive, second_search, cam_shift)
        if event is None:
            return trace
        homed_now = self._reference(
            trace,
            f"{second_search.trigger.replace('_', ' ')} (drive)",
            event,
            trace.phases[-1].segments[-1].t0,
            reference,
            x_end,
        )
        if drive.home_position is not None:
            distance = drive.home_position - homed_now
            if distance:
                s = 1 if distance > 0 else -1
                x_home, _ = _point_to_point(
                    trace,
                    "move to home position",
                    x_end,
                    t,
                    s,
                    drive.velocity,
                    drive.acceleration,
                    abs(distance),
                    "home position reached",
                )
                trace.final_position = homed_now + (x_home - x_end)
        return trace

    def _nc_reference(
        self, trace: Trace, x: float, drive: DriveInput, reference: float, cam_shift: float
    ) -> Trace:
        """TwinCAT NC / AX5000 homing: to the cam, off its falling edge, then the event of the reference mode."""
        scenario = self.scenario
        if scenario.cam is None:
            trace.outcome, trace.failure = (
                "failed",
                "the NC reference modes need a reference cam in the scenario",
            )
            return trace
        lo, hi = scenario.cam[0] + cam_shift, scenario.cam[1] + cam_shift
        toward = (
            1 if drive.invert_cam_search else -1
        )  # the NC searches the cam in negative direction by default
        away = -toward
        sync_speed = drive.velocity_sync or drive.velocity
        saved = self.acceleration, self.cam_level
        self.acceleration, self.cam_level = drive.acceleration, True
        try:
            active, entry, exit_ = self._active(lo, hi)
            t, travelled = 0.0, 0.0
            if not active(x):
                x_end, t, reached = self._edge_move(
                    trace,
                    "to the reference cam",
                    x,
                    t,
                    toward,
                    drive.velocity,
                    entry(x, toward),
                    "the cam was reached",
                    "cam reached",
                    travelled,
                )
                if not reached:
                    return trace
                travelled += abs(x_end - x)
                x = x_end
            edge = exit_(x, away)
            mode = drive.reference_mode
            latched = mode != "plc-cam"
            if mode == "plc-cam":
                distance, event = edge, "falling cam edge"
            else:
                ramp_edge = x + away * edge
                sync = away if not drive.invert_sync_search else toward
                if sync != away:
                    trace.outcome, trace.failure = (
                        "failed",
                        "a sync search back towards the cam is not simulated",
                    )
                    return trace
                if mode == "hardware-sync":
                    distance, event = edge + self._next_pulse(ramp_edge, away), "sync pulse"
                elif mode == "software-sync":
                    period = drive.reference_mask_period or scenario.zero_pulse_period
                    k = (ramp_edge - scenario.zero_pulse_phase) / period
                    n = math.ceil(k - 1e-12) if away > 0 else math.floor(k + 1e-12)
                    distance, event = (
                        edge + abs(scenario.zero_pulse_phase + n * period - ramp_edge),
                        "reference mask overflow",
                    )
                else:
                    if drive.latch_position is None or (drive.latch_position - ramp_edge) * away < 0:
                        trace.outcome, trace.failure = (
                            "failed",
                            "no latch signal after the cam edge (scenario latch_position)",
                        )
                        return trace
                    distance, event = edge + abs(drive.latch_position - ramp_edge), "hardware latch"
            x_end, t, x_ref = self._move(
                trace,
                "off the cam and reference",
                x,
                t,
                away,
                sync_speed,
                distance,
                latched,
                f"the {event} was detected",
                travelled,
            )
            if x_ref is not None:
                self._reference(trace, event, x_ref, trace.phases[-1].segments[-1].t0, reference, x_end)
            return trace
        finally:
            self.acceleration, self.cam_level = saved

    def _drive_search(
        self,
        trace: Trace,
        name: str,
        x: float,
        t: float,
        drive: DriveInput,
        search: SearchInput,
        cam_shift: float,
    ) -> tuple[float, float, float | None]:
        """A search move: direction from the sign of SignedMaxDistance, reversed when the trigger is already active."""
        speed = drive.velocity * search.dynamic_reduction
        sign = 1 if search.signed_max_distance > 0 else -1
        active, crossing = self._trigger(search, cam_shift)
        initially = active(x)
        s = -sign if initially else sign
        distance = crossing(x, s, initially)
        limit = abs(search.signed_max_distance)
        ramp = _Ramp(t, x, s, speed, drive.acceleration)
        trigger = search.trigger.replace("_", " ")

        def stop_at(t_stop: float, note: str) -> tuple[float, float]:
            """Brake from the time `t_stop` after the start; the phase is recorded. Returns (x_end, t_end)."""
            segments, t_end, x_end = ramp.stop(t_stop)
            trace.phases.append(PhaseRecord(name, _dir(s), speed, x, x_end, t, t_end, note, segments))
            return x_end, t_end

        if distance > limit:
            x_end, t_end = stop_at(ramp.time_to(limit), "SignedMaxDistance travelled without a trigger")
            trace.outcome, trace.failure = "failed", f"{name}: no {trigger} within {limit:g} {self.unit}"
            return x_end, t_end, None
        t_event = ramp.time_to(distance)
        if t_event < self.EARLY_TRIGGER:
            x_end, t_end = stop_at(t_event, "early trigger")
            trace.outcome = "failed"
            trace.failure = (
                f"{name}: the trigger came {t_event * 1000:.3g} ms after the start, within the drive's "
                f"5 ms early-trigger window; start farther from it"
            )
            return x_end, t_end, None
        x_end, t_end = stop_at(t_event, f"{trigger} {'left' if initially else 'found'}")
        x_event = x + s * distance
        trace.events.append(Event(t + t_event, x_event, f"{name}: {trigger} edge"))
        return x_end, t_end, x_event

    def _trigger(self, search: SearchInput, cam_shift: float) -> tuple[Active, TriggerEdge]:
        """(is the trigger active at x, distance to its next edge in direction s)."""
        scenario = self.scenario
        if search.trigger == "zero_pulse":
            return (lambda x: False), (lambda x, s, initially: self._next_pulse(x, s))
        if search.trigger in ("fixed_stop", "limit_switch"):
            points = (
                [scenario.fixed_stop]
                if search.trigger == "fixed_stop"
                else list(scenario.limit_switches or ())
            )

            def to_point(x: float, s: int, initially: bool) -> float:
                ahead = [(p - x) * s for p in points if p is not None and (p - x) * s >= 0]
                return min(ahead) if ahead else INF

            return (lambda x: False), to_point
        if scenario.cam is None:
            return (lambda x: False), (lambda x, s, initially: INF)
        lo, hi = scenario.cam[0] + cam_shift, scenario.cam[1] + cam_shift
        low = search.active_low

        def active(x: float) -> bool:
            return (lo <= x <= hi) != low

        def edge(x: float, s: int, initially: bool) -> float:
            inside = lo <= x <= hi
            if inside:
                return hi - x if s > 0 else x - lo
            if s > 0:
                return lo - x if x < lo else INF
            return x - hi if x > hi else INF

        return active, edge


def _point_to_point(
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
    peak = min(speed, math.sqrt(distance * a))
    t_acc = peak / a
    cruise = (distance - peak * peak / a) / peak if peak else 0.0
    segments = [Segment(t, t + t_acc, x, 0.0, s * a)]
    x1 = x + s * peak * peak / (2 * a)
    if cruise > 0:
        segments.append(Segment(t + t_acc, t + t_acc + cruise, x1, s * peak, 0.0))
    t2 = t + t_acc + max(cruise, 0.0)
    x2 = x1 + s * peak * max(cruise, 0.0)
    segments.append(Segment(t2, t2 + t_acc, x2, s * peak, -s * a))
    x_end = x + s * distance
    trace.phases.append(PhaseRecord(name, _dir(s), speed, x, x_end, t, t2 + t_acc, ended_by, segments))
    return x_end, t2 + t_acc


def _dir(s: int) -> str:
    return "positive" if s > 0 else "negative"


def _acceleration(strategy: HomingStrategy, scenario: Scenario) -> tuple[float | None, str]:
    """The acceleration the strategy's moves use, and where it comes from (shown in the header and JSON)."""
    acceleration = strategy.acceleration
    if acceleration is not None:
        return acceleration.ramp, acceleration.words
    drive = scenario.drive
    if drive is None:
        return None, "the drive's own (not simulated without a [drive] table)"
    return drive.acceleration, "the drive's ([drive] acceleration of the scenario)"

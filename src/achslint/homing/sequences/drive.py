"""Drive-controlled homing (§3.1.1.2), simulated when the scenario describes the drive's method: the Triamec
drive homing methods and the TwinCAT NC / AX5000 reference modes."""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import TYPE_CHECKING

from ...catalogue.units import unit_label
from ..motion import (
    INF,
    NOT_SIMULATED,
    Active,
    Event,
    PhaseRecord,
    Ramp,
    Simulator,
    Trace,
    direction_word,
    point_to_point,
)

if TYPE_CHECKING:
    from ..scenario_input import DriveInput, SearchInput

EARLY_TRIGGER = 0.005  # s: a search whose trigger comes sooner is refused by the drive
# A drive search's trigger: the distance from x in direction s to its next edge (active at the start or not).
TriggerEdge = Callable[[float, int, bool], float]


def run(sim: Simulator, trace: Trace, x: float, cam_shift: float) -> Trace:
    """Drive-controlled homing: simulated when the scenario describes the drive's method."""
    if sim.scenario.drive is None:
        return sim.stand_still(
            trace,
            NOT_SIMULATED,
            note="drive-controlled homing: the drive runs its own sequence, not simulated without a "
            "description; describe its method in the scenario's [drive] table to simulate it",
        )
    return _by_method(sim, trace, x, sim.scenario.drive, cam_shift)


def _by_method(sim: Simulator, trace: Trace, x: float, drive: DriveInput, cam_shift: float) -> Trace:
    """The drive's method as the scenario's [drive] table describes it."""
    values = sim.values
    reference = drive.reference_position
    if reference is None:
        reference = sim.refpkt if values.get("kenngr.write_reference_position_to_drive") else 0.0
    if drive.method == "immediate":
        trace.reference = {
            "kind": "immediate (no position set)",
            "position": x,
            "value": x,
            "speed": 0.0,
            "time": 0.0,
        }
        trace.final_position = x
        return trace
    if drive.method == "at-position":
        trace.reference = {
            "kind": "position set at standstill",
            "position": x,
            "value": reference,
            "speed": 0.0,
            "time": 0.0,
        }
        trace.final_position = reference
        return trace
    if drive.method == "absolute-encoder":
        value = x + drive.encoder_offset
        trace.reference = {
            "kind": "absolute encoder offset",
            "position": x,
            "value": value,
            "speed": 0.0,
            "time": 0.0,
        }
        trace.final_position = value
        return trace
    if drive.method == "nc":
        return _nc_reference(sim, trace, x, drive, reference, cam_shift)
    first_search, second_search = drive.first_search, drive.second_search
    if first_search is None or second_search is None:  # refused by DriveInput for the standard method
        raise AssertionError("the standard drive method needs a first and a second search")
    t = 0.0
    x, t, first = _search(sim, trace, "first search", x, t, drive, first_search, cam_shift)
    if first is None:
        return trace
    if drive.relocate_distance:
        s = 1 if drive.relocate_distance > 0 else -1
        x, t = point_to_point(
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
    x_end, t, event = _search(sim, trace, "second search", x, t, drive, second_search, cam_shift)
    if event is None:
        return trace
    homed_now = sim.reference(
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
            x_home, _ = point_to_point(
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
    sim: Simulator, trace: Trace, x: float, drive: DriveInput, reference: float, cam_shift: float
) -> Trace:
    """TwinCAT NC / AX5000 homing: to the cam, off its falling edge, then the event of the reference mode."""
    scenario = sim.scenario
    if scenario.cam is None:
        trace.outcome, trace.failure = (
            "failed",
            "the NC reference modes need a reference cam in the scenario",
        )
        return trace
    lo, hi = scenario.cam[0] + cam_shift, scenario.cam[1] + cam_shift
    toward = 1 if drive.invert_cam_search else -1  # the NC searches the cam in negative direction by default
    away = -toward
    sync_speed = drive.velocity_sync or drive.velocity
    saved = sim.acceleration, sim.cam_level
    sim.acceleration, sim.cam_level = drive.acceleration, True
    try:
        active, entry, exit_ = sim.active_zone(lo, hi)
        t, travelled = 0.0, 0.0
        if not active(x):
            x_end, t, reached = sim.edge_move(
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
                return sim.stand_still(
                    trace,
                    NOT_SIMULATED,
                    note="the sync search back towards the cam (invert_sync_search) is not simulated: the run "
                    "stops after the cam search",
                )
            if mode == "hardware-sync":
                distance, event = edge + sim.next_pulse(ramp_edge, away), "sync pulse"
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
        x_end, t, x_ref = sim.move(
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
            target=f"the {event}",
        )
        if x_ref is not None:
            sim.reference(trace, event, x_ref, trace.phases[-1].segments[-1].t0, reference, x_end)
        return trace
    finally:
        sim.acceleration, sim.cam_level = saved


def _search(
    sim: Simulator,
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
    active, crossing = _trigger(sim, search, cam_shift)
    initially = active(x)
    s = -sign if initially else sign
    distance = crossing(x, s, initially)
    limit = abs(search.signed_max_distance)
    ramp = Ramp(t, x, s, speed, drive.acceleration)
    trigger = search.trigger.replace("_", " ")

    def stop_at(t_stop: float, note: str) -> tuple[float, float]:
        """Brake from the time `t_stop` after the start; the phase is recorded. Returns (x_end, t_end)."""
        segments, t_end, x_end = ramp.stop(t_stop)
        trace.phases.append(PhaseRecord(name, direction_word(s), speed, x, x_end, t, t_end, note, segments))
        return x_end, t_end

    if distance > limit:
        x_end, t_end = stop_at(ramp.time_to(limit), "SignedMaxDistance travelled without a trigger")
        trace.outcome, trace.failure = (
            "failed",
            f"{name}: no {trigger} within {limit:g} {unit_label(sim.unit)}",
        )
        return x_end, t_end, None
    t_event = ramp.time_to(distance)
    if t_event < EARLY_TRIGGER:
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


def _trigger(sim: Simulator, search: SearchInput, cam_shift: float) -> tuple[Active, TriggerEdge]:
    """(is the trigger active at x, distance to its next edge in direction s)."""
    scenario = sim.scenario
    if search.trigger == "zero_pulse":
        return (lambda x: False), (lambda x, s, initially: sim.next_pulse(x, s))
    if search.trigger in ("fixed_stop", "limit_switch"):
        points = (
            [scenario.fixed_stop] if search.trigger == "fixed_stop" else list(scenario.limit_switches or ())
        )

        def to_point(x: float, s: int, initially: bool) -> float:
            ahead = [(p - x) * s for p in points if p is not None and (p - x) * s >= 0]
            return min(ahead) if ahead else INF

        return (lambda x: False), to_point
    if scenario.cam is None:
        return (lambda x: False), (lambda x, s, initially: INF)
    lo, hi = scenario.cam[0] + cam_shift, scenario.cam[1] + cam_shift
    low = search.active_low
    if sim.modulo:
        return _modulo_cam(lo, hi, low, sim.revolution)

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


def _modulo_cam(lo: float, hi: float, low: bool, period: float) -> tuple[Active, TriggerEdge]:
    """The cam trigger of a modulo axis: the cam [lo, hi] recurs every revolution, so a search that wraps past
    the modulo range meets it on the next revolution (its distance is always finite)."""
    width = hi - lo

    def offset(x: float) -> float:  # where x lies past the cam's start, within one revolution
        return (x - lo) % period

    def active(x: float) -> bool:
        return (offset(x) <= width) != low

    def edge(x: float, s: int, initially: bool) -> float:
        r = offset(x)
        if r <= width:  # on the cam: to its end (s > 0) or back to its start
            return width - r if s > 0 else r
        return period - r if s > 0 else r - width  # off the cam: to its next start or back to its end

    return active, edge

"""CNC-controlled homing with a reference cam (§2.3.1, §2.3.3.2): three phases, or one without reversal,
referencing on the cam edge (types I) or on the next zero pulse after it (type III)."""

from __future__ import annotations

import math

from ...catalogue.units import unit_label
from ..motion import (
    INF,
    ZERO_SEARCH_EXCEEDED,
    Active,
    Arming,
    Crossing,
    Event,
    Ramp,
    Segment,
    Simulator,
    StartOnCam,
    Trace,
)
from . import _zero_pulse


def _cam(sim: Simulator, trace: Trace, cam_shift: float) -> tuple[Active, Crossing, Crossing] | None:
    """Where the cam signal is active in this run (the scenario's cam moved by the jitter `cam_shift`); None,
    and homing failed, when the scenario has no cam."""
    if sim.scenario.cam is None:
        sim.stand_still(trace, "failed", "the strategy needs a reference cam but the scenario has none")
        return None
    lo, hi = sim.scenario.cam
    return sim.active_zone(lo + cam_shift, hi + cam_shift)


def reference_search(
    sim: Simulator,
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
    scenario = sim.scenario
    if not sim.strategy.with_zero_pulse:
        x_end, _t_end, x_cam = sim.move(
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
            target="the cam edge",
        )
        if x_cam is not None:
            t_cam = trace.phases[-1].segments[-1].t0
            trace.events.append(Event(t_cam, x_cam, "cam edge detected"))
            sim.reference(trace, "cam edge", x_cam, t_cam, sim.refpkt, x_end)
        return trace
    if cam_distance > sim.bound(x, s, travelled)[0]:
        # The cam is never reached: the move ends at a limit and homing fails.
        sim.move(trace, name, x, t, s, speed, cam_distance, False, "", travelled, target="the cam edge")
        return trace
    # The cam edge is sampled; the zero-pulse logic starts `shift` later; the pulse itself may be latched.
    ramp = Ramp(t, x, s, speed, sim.ramp_acceleration)
    t_cam = sim.sample(ramp, cam_distance, False)
    x_cam = x + s * ramp.distance_at(t_cam)
    activation = x_cam + s * sim.shift
    pulse_distance = abs(activation - x) + sim.next_pulse(activation, s)
    event = "encoder overflow" if sim.overflow else "zero pulse"
    latched = scenario.hardware_latch or sim.overflow
    _zero_pulse.pulse_margin(sim, trace, activation, s, speed)
    # zero_pulse_search_max_dist counts from where the zero-pulse logic is armed (the cam edge plus the shift):
    # the manual does not say; this is the reading under which the shift cannot make a pulse unreachable.
    before = abs(activation - x) if sim.zero_search_max > 0 else 0.0
    search_max = sim.zero_search_max if sim.zero_search_max > 0 else INF
    x_end, _t_end, x_ref = sim.move(
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
        target=f"the {event} after the cam",
    )
    if cam_distance <= abs(x_end - x) or x_ref is not None:
        _zero_pulse.arming_events(sim, trace, "cam edge detected", t + t_cam, x_cam, s)
        trace.arming = Arming(x_cam, activation)
    if x_ref is not None:
        t_ref = trace.phases[-1].segments[-1].t0
        sim.reference(trace, event, x_ref, t_ref, sim.refpkt, x_end)
    return trace


def three_phases(sim: Simulator, trace: Trace, x: float, cam_shift: float) -> Trace:
    """Default homing (§2.3.1): to the cam at vb_refmax (skipped when starting on it), back off it (at vb_refmax
    with fast_from_cam), and slowly onto it again, referencing on its edge or the next zero pulse."""
    zone = _cam(sim, trace, cam_shift)
    if zone is None:
        return trace
    active, entry, exit_ = zone
    s = sim.direction
    t = 0.0
    fast = sim.fast
    slow = sim.slow
    travelled = 0.0
    if active(x):
        trace.events.append(Event(0.0, x, "on the cam at the start: phase 1 skipped"))
    else:
        x_end, t, reached = sim.edge_move(
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
                f"{fast * fast / (2 * sim.ramp_acceleration):.4g} {unit_label(sim.unit)} is longer than the cam)"
            )
            return trace
    speed = fast if sim.fast_from_cam else slow
    x_end, t, left = sim.edge_move(
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
        target="the end of the cam",
    )
    if not left:
        return trace
    travelled += abs(x_end - x)
    x = x_end
    return reference_search(sim, trace, "onto the cam and reference", x, t, s, slow, entry(x, s), travelled)


def one_phase(sim: Simulator, trace: Trace, x: float, cam_shift: float) -> Trace:
    """Homing without reversal (§2.3.3.2): the cam is approached at vb_refmax and the reference is its edge
    (type I) or the next zero pulse, searched at vb_reflow (type III). An axis that starts on the cam references
    without leaving it (StartOnCam, LIS402)."""
    zone = _cam(sim, trace, cam_shift)
    if zone is None:
        return trace
    active, entry, _exit = zone
    s = sim.direction
    if active(x):
        trace.facts.append(StartOnCam(x))
    if not sim.strategy.with_zero_pulse:
        return reference_search(sim, trace, "to the cam and reference", x, 0.0, s, sim.fast, entry(x, s), 0.0)
    if active(x):  # on the cam already (LIS402): the logic is armed where the axis stands
        return reference_search(sim, trace, "on to the reference", x, 0.0, s, sim.slow, 0.0, 0.0)
    return one_phase_zero_pulse(sim, trace, x, s, entry(x, s))


def one_phase_zero_pulse(sim: Simulator, trace: Trace, x: float, s: int, cam_distance: float) -> Trace:
    """One-phase homing on the cam and the zero pulse (§2.3.3.2) from a start off the cam.

    The cam is approached at vb_refmax and its edge sampled each cycle. The zero-pulse logic is armed at
    that point, or shift_offset_zero_pulse_activation further on (§2.6: enabled as soon as the cam is
    operated), whatever the axis does there: the first pulse after the arming point is the reference.
    After the cam the axis brakes to a stop; a pulse passed while braking ends homing there (the axis is
    already braking). Otherwise it searches on at vb_reflow, from where it stopped, and brakes after the
    pulse. zero_pulse_search_max_dist counts from the arming point."""
    x_stop, t_stop, reached = sim.edge_move(
        trace,
        "to the reference cam",
        x,
        0.0,
        s,
        sim.fast,
        cam_distance,
        "the cam was reached (sampled each cycle)",
        "cam reached" if sim.shift else "cam reached, zero-pulse logic armed",
        0.0,
    )
    if not reached:
        return trace
    cam = trace.events[-1]
    armed = cam.position + s * sim.shift
    trace.arming = Arming(cam.position, armed)
    pulse = armed + s * sim.next_pulse(armed, s)
    event = "encoder overflow" if sim.overflow else "zero pulse"
    latched = sim.scenario.hardware_latch or sim.overflow
    # The arming point inherits the cam's spread: its jitter and the sampling at the approach speed.
    _zero_pulse.pulse_margin(sim, trace, armed, s, sim.fast)
    search_max = sim.zero_search_max if sim.zero_search_max > 0 else INF
    found = s * (pulse - armed) <= search_max
    stop_at = pulse if found else armed + s * search_max  # where the search ends: pulse or search limit
    if s * (x_stop - stop_at) >= 0:  # passed while braking after the cam
        if sim.shift:
            _zero_pulse.arming_events(sim, trace, "", cam.time, cam.position, s)
        return _end_while_braking(sim, trace, stop_at, found, latched, event, s, pulse)
    x_end, _t_end, x_ref = sim.move(
        trace,
        "on to the reference",
        x_stop,
        t_stop,
        s,
        sim.slow,
        s * (pulse - x_stop),
        latched,
        f"the {event} was detected" + ("" if latched else " (sampled each cycle)"),
        abs(x_stop - x),
        search_max,
        s * (armed - x_stop),
        target=f"the {event} after the arming point",
    )
    if sim.shift:
        _zero_pulse.arming_events(sim, trace, "", cam.time, cam.position, s)
    if x_ref is not None:
        sim.reference(trace, event, x_ref, trace.phases[-1].segments[-1].t0, sim.refpkt, x_end)
    return trace


def _end_while_braking(
    sim: Simulator, trace: Trace, point: float, found: bool, latched: bool, event: str, s: int, pulse: float
) -> Trace:
    """The search ends at `point` while the axis brakes after the cam: at the reference event (`found`) or
    at the search limit, short of the `pulse`. The braking segment is split there, so the reference's speed
    is the speed then."""
    phase = trace.phases[-1]
    t_pass = sim.passing_time(trace, point, s, phase.segments[-1].t0)
    if t_pass is None:  # pragma: no cover - the point lies within the braking travel
        raise AssertionError("a point within the braking travel is passed")
    if not found:
        phase.ended_by = ZERO_SEARCH_EXCEEDED
        sim.stopped(
            trace,
            phase.name,
            ZERO_SEARCH_EXCEEDED,
            s,
            f"the {event}",
            pulse,
            0.0,
            " while braking after the cam",
        )
        return trace
    t_detect = t_pass
    if not latched:
        cycle = sim.scenario.cycle_time
        t_detect = min(max(math.ceil(t_pass / cycle - 1e-9) * cycle, t_pass), phase.end_time)
    braking = phase.segments.pop()
    x_detect, v_detect = braking.position(t_detect), braking.velocity(t_detect)
    phase.segments += [
        Segment(braking.t0, t_detect, braking.x0, braking.v0, braking.a),
        Segment(t_detect, braking.t1, x_detect, v_detect, braking.a),
    ]
    phase.ended_by = f"{phase.ended_by}; the {event} was detected while braking"
    sim.reference(trace, event, x_detect, t_detect, sim.refpkt, phase.end_position)
    return trace

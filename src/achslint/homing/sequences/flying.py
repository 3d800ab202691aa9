"""Flying homing of a spindle (§2.3.2.1): no reversal and no stop."""

from __future__ import annotations

from ...catalogue.units import unit_label
from ..motion import INF, Arming, Event, PhaseRecord, Ramp, Segment, Simulator, Trace, direction_word
from . import _zero_pulse


def run(sim: Simulator, trace: Trace, x: float, cam_shift: float) -> Trace:
    """Flying homing of a spindle (§2.3.2.1): no reversal and no stop.

    From standstill the spindle turns in the homing direction (ref_richt) and accelerates to vb_reflow with
    its default ramps. From endless rotation (the scenario's `start_velocity`) it keeps its rotation
    direction and "first accelerates or decelerates to the homing speed vb_reflow before being referenced":
    the referencing starts where it runs at vb_reflow (the tool's reading of "before"; a cam edge or a pulse
    passed while the speed changes does not count). With a cam (ref_ohne_nocken 0) the cam counts where it
    changes from operated to not operated: a spindle off the cam turns onto it and through it, one on the cam
    turns until it leaves it; that edge (sampled each cycle) arms the zero-pulse logic,
    shift_offset_zero_pulse_activation later. Without a cam the logic is armed where the referencing starts.
    The next zero pulse is the reference, and the spindle keeps turning at the speed it has: the trace ends
    at the reference event, moving."""
    speed = sim.slow
    turning = sim.scenario.start_velocity
    s = (1 if turning > 0 else -1) if turning else sim.direction
    scenario = sim.scenario
    ramp = Ramp(0.0, x, s, speed, sim.ramp_acceleration, abs(turning))
    lead = ramp.d_acc if turning else 0.0  # travel before the referencing starts
    t_start = ramp.t_acc if turning else 0.0
    start = x + s * lead
    name = "reference on the fly"
    if turning:
        _rotation_events(sim, trace, x, start, t_start, turning, ramp)
        bound, reason = sim.bound(x, s)
        if lead > bound:
            return _abort(sim, trace, ramp, name, bound, reason, "vb_reflow", lead)
    t_edge = None
    cam_at: float | None = None  # where the cam counts as operated (its not-operated edge)
    if sim.strategy.with_cam:
        if scenario.cam is None:
            return sim.stand_still(
                trace, "failed", "flying homing with cam needs a reference cam but the scenario has none"
            )
        lo, hi = scenario.cam[0] + cam_shift, scenario.cam[1] + cam_shift
        active, entry, exit_ = sim.active_zone(lo, hi)
        if active(start):
            edge = lead + exit_(start, s)
            where = "when the referencing starts" if turning else "at the start"
            trace.events.append(Event(t_start, start, f"on the cam {where}: turns until the cam is left"))
        else:
            span = (hi - lo) if sim.cam_level else (sim.revolution or INF) - (hi - lo)
            edge = lead + entry(start, s) + span
        bound, reason = sim.bound(x, s)
        if edge > bound:
            return _abort(sim, trace, ramp, name, bound, reason, "the end of the cam", edge)
        t_edge = sim.sample(ramp, edge, False)
        cam_at = x + s * ramp.distance_at(t_edge)
        activation = cam_at + s * sim.shift
    else:
        activation = start
    trace.arming = Arming(cam_at, activation)
    event = "encoder overflow" if sim.overflow else "zero pulse"
    latched = scenario.hardware_latch or sim.overflow
    distance = abs(activation - x) + sim.next_pulse(activation, s)
    extra = abs(activation - x) + sim.zero_search_max if sim.zero_search_max > 0 else INF
    bound, reason = sim.bound(x, s, 0.0, extra)
    if distance > bound:
        return _abort(sim, trace, ramp, name, bound, reason, f"the {event}", distance, t_edge)
    if t_edge is not None:
        _zero_pulse.pulse_margin(sim, trace, activation, s, speed)
    t_ref = sim.sample(ramp, distance, latched)
    x_ref = x + s * ramp.distance_at(t_ref)
    segments = ramp.run_until(t_ref)
    way = direction_word(s)
    ended = f"the {event} was detected; the spindle turns on without stopping"
    if turning and ramp.t_acc:
        change = "decelerate" if ramp.k < 0 else "accelerate"
        trace.phases.append(
            PhaseRecord(
                f"{change} to vb_reflow (from endless rotation)",
                way,
                speed,
                x,
                start,
                0.0,
                t_start,
                "vb_reflow reached in the rotation direction: the referencing starts (§2.3.2.1)",
                segments[:1],
            )
        )
        cruise = segments[1:] or [Segment(t_start, t_start, start, s * speed, 0.0)]
        trace.phases.append(PhaseRecord(name, way, speed, start, x_ref, t_start, t_ref, ended, cruise))
    else:
        trace.phases.append(PhaseRecord(name, way, speed, x, x_ref, 0.0, t_ref, ended, segments))
    if t_edge is not None:
        _edge_event(sim, trace, t_edge, x + s * ramp.distance_at(t_edge), s)
    trace.events.append(Event(t_ref, x_ref, event))
    trace.reference_at = x_ref
    trace.reference = {
        "kind": event,
        "position": sim.wrap(x_ref),
        "value": sim.refpkt,
        "speed": ramp.speed_at(t_ref),
        "time": t_ref,
    }
    trace.final_position = sim.wrap(sim.refpkt)
    trace.ends_moving = True
    return trace


def _rotation_events(
    sim: Simulator, trace: Trace, x: float, start: float, t_start: float, turning: float, ramp: Ramp
) -> None:
    """Where the spindle turned endlessly at the start, and where it runs at vb_reflow."""
    rate = f"{unit_label(sim.unit)}/s"
    way = direction_word(ramp.s)
    if not ramp.t_acc:
        trace.events.append(
            Event(0.0, x, f"turning {way} at {abs(turning):g} {rate} = vb_reflow: the referencing starts")
        )
        return
    change = "decelerates" if ramp.k < 0 else "accelerates"
    trace.events.append(
        Event(0.0, x, f"turning {way} at {abs(turning):g} {rate} (endless rotation): {change} to vb_reflow")
    )
    trace.events.append(
        Event(t_start, start, f"vb_reflow ({ramp.v:g} {rate}) reached: the referencing starts")
    )


def _edge_event(sim: Simulator, trace: Trace, t: float, position: float, s: int) -> None:
    _zero_pulse.arming_events(sim, trace, "cam left", t, position, s)


def _abort(
    sim: Simulator,
    trace: Trace,
    ramp: Ramp,
    name: str,
    bound: float,
    reason: str,
    target: str,
    distance: float,
    t_edge: float | None = None,
) -> Trace:
    """A flying search that a bound ends before `target`, `distance` ahead: the CNC aborts homing and the
    spindle brakes."""
    segments, t_end, x_end = ramp.stop(ramp.time_to(bound))
    trace.phases.append(
        PhaseRecord(name, direction_word(ramp.s), ramp.v, ramp.x0, x_end, ramp.t0, t_end, reason, segments)
    )
    if t_edge is not None and t_edge <= ramp.time_to(bound):
        _edge_event(sim, trace, t_edge, ramp.x0 + ramp.s * ramp.distance_at(t_edge), ramp.s)
    sim.stopped(trace, name, reason, ramp.s, target, ramp.x0, distance)
    return trace

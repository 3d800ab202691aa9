"""Flying homing of a spindle (§2.3.2.1): no reversal and no stop."""

from __future__ import annotations

from ..motion import INF, Arming, Event, PhaseRecord, Ramp, Simulator, Trace, direction_word
from . import _zero_pulse


def run(sim: Simulator, trace: Trace, x: float, cam_shift: float) -> Trace:
    """Flying homing of a spindle (§2.3.2.1): no reversal and no stop.

    The spindle turns in the homing direction at vb_reflow with its default ramps. With a cam
    (ref_ohne_nocken 0) the cam counts where it changes from operated to not operated: a spindle off the
    cam turns onto it and through it, one on the cam turns until it leaves it; that edge (sampled each
    cycle) arms the zero-pulse logic, shift_offset_zero_pulse_activation later. Without a cam the logic
    is armed at once. The next zero pulse is the reference, and the spindle keeps turning at the speed it
    has: the trace ends at the reference event, moving."""
    s, speed = sim.direction, sim.slow
    scenario = sim.scenario
    ramp = Ramp(0.0, x, s, speed, sim.ramp_acceleration)
    name = "reference on the fly"
    t_edge = None
    cam_at: float | None = None  # where the cam counts as operated (its not-operated edge)
    if sim.strategy.with_cam:
        if scenario.cam is None:
            return sim.stand_still(
                trace, "failed", "flying homing with cam needs a reference cam but the scenario has none"
            )
        lo, hi = scenario.cam[0] + cam_shift, scenario.cam[1] + cam_shift
        active, entry, exit_ = sim.active_zone(lo, hi)
        if active(x):
            edge = exit_(x, s)
            trace.events.append(Event(0.0, x, "on the cam at the start: turns until the cam is left"))
        else:
            span = (hi - lo) if sim.cam_level else (sim.revolution or INF) - (hi - lo)
            edge = entry(x, s) + span
        bound, reason = sim.bound(x, s)
        if edge > bound:
            return _abort(sim, trace, ramp, name, bound, reason)
        t_edge = sim.sample(ramp, edge, False)
        cam_at = x + s * ramp.distance_at(t_edge)
        activation = cam_at + s * sim.shift
    else:
        activation = x
    trace.arming = Arming(cam_at, activation)
    event = "encoder overflow" if sim.overflow else "zero pulse"
    latched = scenario.hardware_latch or sim.overflow
    distance = abs(activation - x) + sim.next_pulse(activation, s)
    extra = abs(activation - x) + sim.zero_search_max if sim.zero_search_max > 0 else INF
    bound, reason = sim.bound(x, s, 0.0, extra)
    if distance > bound:
        return _abort(sim, trace, ramp, name, bound, reason, t_edge, x)
    if t_edge is not None:
        _zero_pulse.pulse_margin(sim, trace, activation, s, speed)
    t_ref = sim.sample(ramp, distance, latched)
    x_ref = x + s * ramp.distance_at(t_ref)
    segments = ramp.run_until(t_ref)
    trace.phases.append(
        PhaseRecord(
            name,
            direction_word(s),
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
        _edge_event(sim, trace, t_edge, x + s * ramp.distance_at(t_edge))
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


def _edge_event(sim: Simulator, trace: Trace, t: float, position: float) -> None:
    _zero_pulse.arming_events(sim, trace, "cam left", t, position, sim.direction)


def _abort(
    sim: Simulator,
    trace: Trace,
    ramp: Ramp,
    name: str,
    bound: float,
    reason: str,
    t_edge: float | None = None,
    x: float = 0.0,
) -> Trace:
    """A flying search that a bound ends: the CNC aborts homing and the spindle brakes."""
    segments, t_end, x_end = ramp.stop(ramp.time_to(bound))
    trace.phases.append(
        PhaseRecord(name, direction_word(ramp.s), ramp.v, ramp.x0, x_end, ramp.t0, t_end, reason, segments)
    )
    if t_edge is not None and t_edge <= ramp.time_to(bound):
        _edge_event(sim, trace, t_edge, ramp.x0 + ramp.s * ramp.distance_at(t_edge))
    trace.outcome, trace.failure = "failed", f"{name}: {reason} before the event was found"
    return trace

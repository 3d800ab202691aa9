"""Referencing on the zero pulse without a reference cam (type II, §2.3.3.3)."""

from __future__ import annotations

from ..motion import INF, Arming, Simulator, Trace


def run(sim: Simulator, trace: Trace, x: float, cam_shift: float) -> Trace:
    """At vb_reflow in the homing direction to the first zero pulse (or encoder overflow), bounded by
    zero_pulse_search_max_dist; without a zero pulse nothing marks the reference."""
    if not sim.strategy.setup.zero_pulse:
        return sim.stand_still(
            trace, "failed", "neither a reference cam nor a zero pulse marks the reference (LIS318)"
        )
    s = sim.direction
    speed = sim.slow
    event = "encoder overflow" if sim.overflow else "zero pulse"
    latched = sim.scenario.hardware_latch or sim.overflow
    search_max = sim.zero_search_max if sim.zero_search_max > 0 else INF
    trace.arming = Arming(None, x)  # without a cam the zero-pulse logic is armed at the start (§2.3.3.3)
    x_end, _t_end, x_ref = sim.move(
        trace,
        f"to the {event}",
        x,
        0.0,
        s,
        speed,
        sim.next_pulse(x, s),
        latched,
        f"the {event} was detected",
        0.0,
        search_max,
        target=f"the {event}",
    )
    if x_ref is not None:
        sim.reference(trace, event, x_ref, trace.phases[-1].segments[-1].t0, sim.refpkt, x_end)
    return trace

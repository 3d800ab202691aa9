"""A simulated drive (§3.4): one move over the simulated distance to the zero pulse."""

from __future__ import annotations

from ..motion import POSITION, Simulator, Trace


def run(sim: Simulator, trace: Trace, x: float, cam_shift: float) -> Trace:
    """At vb_reflow in the homing direction over rpf_weg_bis_nip, where the simulated (latched) zero pulse is
    the reference; the drive has no cam, so the cam shift does not matter."""
    s = sim.direction
    speed = sim.slow
    distance = abs(sim.values.number("antr.simu.rpf_weg_bis_nip")) * POSITION
    x_end, _t_end, x_ref = sim.move(
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
        target="the simulated zero pulse",
    )
    if x_ref is not None:
        sim.reference(
            trace, "simulated zero pulse", x_ref, trace.phases[-1].segments[-1].t0, sim.refpkt, x_end
        )
    return trace

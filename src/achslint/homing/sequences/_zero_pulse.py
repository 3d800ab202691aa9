"""The zero-pulse logic of §2.6, shared by the sequences that reference on a zero pulse after a cam edge:
where it is armed (events) and how close the pulse it takes lies to that point (LIS405's fact)."""

from __future__ import annotations

from ...catalogue.units import unit_label
from ..motion import Event, PulseMargin, Simulator, Trace


def pulse_margin(sim: Simulator, trace: Trace, activation: float, s: int, speed: float) -> None:
    """Record a zero pulse so close to the arming point that the cam's spread can put it on either side.

    The arming point moves with the cam edge: by the scenario's cam jitter and by the sampling of the edge,
    one cycle at the speed the cam is crossed (vb_reflow in three phases, vb_refmax in one phase). The fact
    holds the shift that puts the pulse half a revolution away and what it does to the reference: the logic
    armed at (wanted - shift) further on takes the pulse half a period after it, so the reference moves by
    wanted - shift + period/2 - ahead along the homing direction, a whole number of pulse periods, and
    pos_refpkt must move with it."""
    period, _ = sim.pulse_lattice()
    ahead = sim.next_pulse(activation, s)  # the pulse the logic takes
    behind = period - ahead  # the pulse just before the arming point
    margin = speed * sim.scenario.cycle_time + sim.scenario.cam_jitter
    if ahead >= margin and behind >= margin:
        return
    wanted = (sim.shift + ahead - period / 2) % period
    periods = round((wanted - sim.shift + period / 2 - ahead) / period)
    moved = s * periods * period  # in the scenario frame
    if sim.modulo:  # a whole revolution of a modulo axis is the same position
        half = sim.revolution / 2
        moved = (moved + half) % sim.revolution - half
    trace.facts.append(
        PulseMargin(
            ahead,
            behind,
            margin,
            period,
            wanted,
            periods,
            moved,
            sim.wrap(sim.refpkt + moved),
            sim.modulo,
            sim.strategy.gear,
            sim.unit,
        )
    )


def arming_events(sim: Simulator, trace: Trace, cam_kind: str, t_cam: float, x_cam: float, s: int) -> None:
    """The events of the zero-pulse logic (§2.6): where the cam was operated and where the logic was armed.

    Without shift_offset_zero_pulse_activation both are one point (`cam_kind`, zero-pulse logic armed);
    with it the arming point follows the shift later, as its own event once the axis has passed it.
    An empty `cam_kind` adds only the arming event (the cam event is already in the trace)."""
    if not sim.shift:
        trace.events.append(Event(t_cam, x_cam, f"{cam_kind}, zero-pulse logic armed"))
        return
    if cam_kind:
        trace.events.append(Event(t_cam, x_cam, cam_kind))
    armed = x_cam + s * sim.shift
    t_armed = sim.passing_time(trace, armed, s, t_cam)
    if t_armed is not None:
        kind = (
            f"zero-pulse logic armed ({sim.shift:g} {unit_label(sim.unit)} after the cam edge, P-AXIS-00494)"
        )
        trace.events.append(Event(t_armed, armed, kind))

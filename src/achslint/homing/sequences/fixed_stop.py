"""Homing to a fixed stop (`TORQ`, §2.3.3.4): move with limited torque until the stop is detected, then retract."""

from __future__ import annotations

from ...catalogue.units import unit_label
from ..motion import (
    POSITION,
    VELOCITY,
    Event,
    PhaseRecord,
    Ramp,
    Segment,
    Simulator,
    Trace,
    direction_word,
    number,
    point_to_point,
)


def run(sim: Simulator, trace: Trace, x: float, cam_shift: float) -> Trace:
    """To the stop at torq_move_velocity (the simulated drive's stop lies torq_distance_to_block away, a real
    one where the scenario puts it), detected after torq_detect_time once past torq_min_distance; the stop
    gets torq_homing_position and the axis retracts by torq_retraction_distance."""
    values, gear = sim.values, sim.strategy.gear
    s = sim.direction  # torq_homing_dir
    speed = values.number(f"getriebe[{gear}].homing.torq_move_velocity") * VELOCITY
    acceleration = values.number(f"getriebe[{gear}].homing.torq_move_acceleration")
    if speed <= 0 or acceleration <= 0:
        missing = "torq_move_velocity" if speed <= 0 else "torq_move_acceleration"
        trace.outcome, trace.failure = (
            "failed",
            f"{missing} is not set (0): the axis does not move (LIS315)",
        )
        return trace
    if sim.strategy.setup.simulated:
        stop: float | None = x + s * values.number("kenngr.homing.torq_distance_to_block") * POSITION
    else:
        stop = sim.scenario.fixed_stop
    reach = (stop - x) * s if stop is not None else 0.0
    min_distance = values.number("kenngr.homing.torq_min_distance") * POSITION
    max_distance = values.number("kenngr.homing.torq_max_distance") * POSITION
    ramp = Ramp(0.0, x, s, speed, float(acceleration))
    if stop is None or reach <= 0 or (max_distance > 0 and reach > max_distance):
        limit = max_distance if max_distance > 0 else sim.bound(x, s, 0.0)[0]
        segments, t_end, x_end = ramp.stop(ramp.time_to(limit))
        trace.phases.append(
            PhaseRecord(
                "to the fixed stop",
                direction_word(s),
                speed,
                x,
                x_end,
                0.0,
                t_end,
                "torq_max_distance travelled without a stop",
                segments,
            )
        )
        unit = unit_label(sim.unit)
        if stop is not None and reach > 0:
            trace.searched = ("the fixed stop", stop)
            beyond = f"the fixed stop at {number(stop)} {unit} lies {number(reach)} {unit} away"
        else:
            beyond = f"the scenario has no fixed stop ahead in the {direction_word(s)} direction"
        limit_words = (
            f"torq_max_distance ({number(max_distance)} {unit})"
            if max_distance > 0
            else f"torq_max_distance (0: bounded by {sim.bound(x, s, 0.0)[1]})"
        )
        trace.outcome, trace.failure = (
            "failed",
            f"no fixed stop within {limit_words}: {beyond}; homing aborted",
        )
        return trace
    t_contact = ramp.time_to(reach)
    # At the stop the axis is blocked: the motion ends abruptly at the stop position.
    segments = ramp.stop(t_contact)[0][:-1]
    segments.append(Segment(t_contact, t_contact, stop, 0.0, 0.0))
    if reach < min_distance:
        trace.phases.append(
            PhaseRecord(
                "to the fixed stop",
                direction_word(s),
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
            ("the stop lies within torq_min_distance: detection is not armed yet when the axis is blocked"),
        )
        return trace
    detect = values.number("kenngr.homing.torq_detect_time") * 1e-6
    t_detect = t_contact + detect
    segments.append(Segment(t_contact, t_detect, stop, 0.0, 0.0))
    trace.phases.append(
        PhaseRecord(
            "to the fixed stop",
            direction_word(s),
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
    trace.reference = {"kind": "fixed stop", "position": stop, "value": value, "speed": 0.0, "time": t_detect}
    x_end, t_end = point_to_point(
        trace, "retract from the stop", stop, t_detect, -s, speed, float(acceleration), retraction
    )
    trace.final_position = value + (x_end - stop)
    return trace

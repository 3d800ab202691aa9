"""Drive-side searches on modulo axes (issue 26 item 5): a Triamec search that wraps past the modulo range finds the
cam on its next revolution, as the CNC-controlled and the NC / AX5000 modes already do. The axis: a SERCOS drive
homing itself (P-AXIS-00299 DRIVE_CONTROLLED) on a rotary axis counting modulo 360° (P-AXIS-00015 MODULO)."""

from __future__ import annotations

from typing import Any

from achslint.dryrun import dry_run
from achslint.homing.motion import Trace
from achslint.homing.scenario import ScenarioInput

from .engine_scene import approx

ROTARY_DRIVE = b"kenngr.antr_typ 2\nkenngr.achs_typ 2\nkenngr.achs_mode 0x4\nkenngr.homing.homing_type DRIVE_CONTROLLED\nEnde\n"
# 20 °/s at 200 °/s²: t_acc 0.1 s, d_acc 1°, braking 1°.
STANDARD: dict[str, Any] = {
    "method": "standard",
    "velocity": 20.0,
    "acceleration": 200.0,
    "reference_position": 0.0,
    "first_search": {"trigger": "cam", "signed_max_distance": 400.0},
    "second_search": {"trigger": "zero_pulse", "signed_max_distance": -10.0},
}


def drive(start: float, method: dict[str, Any], cam: tuple[float, float] = (40.0, 50.0)) -> Trace:
    scenario = ScenarioInput(
        start_position=start, cam=cam, zero_pulse_period=5.0, zero_pulse_phase=2.0, drive=method
    )
    return dry_run(ROTARY_DRIVE, "r.lis", scenario).trace


def test_a_first_search_wraps_past_360_to_the_cam_of_the_next_revolution():
    trace = drive(60.0, STANDARD)
    # From 60° positive the cam [40, 50] lies behind; on the next revolution it starts at 400° (= 40°), 340° away,
    # within the 400° SignedMaxDistance: found at t = 0.1 + 339/20 = 17.05 s; the axis brakes 1° to 401°.
    # Second search negative for a zero pulse (every 5° at 2°: ..., 397, 402): 397° is 4° back:
    # t = 0.1 + 3/20 = 0.25 s after the first search ended. 397° is 37° within the modulo range.
    assert trace.outcome == "homed", trace.failure
    first, second = trace.phases
    assert first.ended_by == "cam found" and approx(first.end_position, 401.0)
    cam = next(e for e in trace.events if e.kind == "first search: cam edge")
    assert approx(cam.position, 400.0) and approx(cam.time, 17.05)
    assert second.direction == "negative" and approx(second.end_position, 396.0)
    assert approx(trace.reference["position"], 37.0) and trace.reference["value"] == 0.0


def test_a_search_starting_on_the_cam_reverses_and_leaves_it_on_a_modulo_axis():
    # Starting at 405° (= 45°, on the cam) the trigger is active: the search reverses (negative) and ends at the
    # cam's start of this revolution, 400°, 5° away: t = 0.1 + 4/20 = 0.3 s.
    trace = drive(405.0, STANDARD)
    assert trace.phases[0].direction == "negative" and trace.phases[0].ended_by == "cam left"
    assert approx(trace.events[0].position, 400.0) and approx(trace.events[0].time, 0.3)


def test_a_search_shorter_than_the_way_round_still_fails_with_its_distance():
    # 300° of SignedMaxDistance does not reach the next cam 340° away: the drive reports no cam within 300°.
    trace = drive(60.0, {**STANDARD, "first_search": {"trigger": "cam", "signed_max_distance": 300.0}})
    assert trace.outcome == "failed" and trace.failure == "first search: no cam within 300 °"

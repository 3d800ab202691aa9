"""Dry-run outcomes the engine tests leave out: a cam too short to stop on, a one-phase search that never
meets its cam, fixed stops closer than torq_min_distance or on a simulated drive, and the drive-side
methods that end early (no trigger within the distance, sync search back, no latch signal).

Numbers are worked out by hand in the comments: ramps are trapezoidal, t_acc = v/a, d_acc = v²/2a."""

from __future__ import annotations

import pytest

from achslint.dryrun import dry_run
from achslint.homing.motion import Trace
from achslint.scenario import ScenarioInput

# Conventional drive, linear axis, homing negative: fast 100 mm/s, slow 10 mm/s, 500 mm/s².
AXIS = (
    "kenngr.antr_typ 1\nkenngr.ref_richt 0\nkenngr.fast_from_cam 1\n"
    "getriebe[0].vb_refmax 100000\ngetriebe[0].vb_reflow 10000\ngetriebe[0].a_ref 500\n"
    "getriebe[0].pos_refpkt -9500000\n"
)
SCENE = {
    "start_position": 0.0,
    "cam": (-120.0, -100.0),
    "zero_pulse_period": 5.0,
    "zero_pulse_phase": -102.5,
    "hardware_latch": True,
    "cycle_time_ms": 1.0,
    "limit_switches": (-1010.0, 1010.0),
}
TORQ = (
    "kenngr.homing.homing_type TORQ\nkenngr.homing.torq_homing_dir POSITIVE\n"
    "getriebe[0].homing.torq_move_velocity 5000\ngetriebe[0].homing.torq_move_acceleration 50\n"
    "kenngr.homing.torq_detect_time 25000\n"
)
SERCOS_DRIVE = b"kenngr.antr_typ 2\nkenngr.homing.homing_type DRIVE_CONTROLLED\nEnde\n"


def approx(value: float, expected: float, tolerance: float = 1e-9) -> bool:
    return value == pytest.approx(expected, abs=tolerance)


def run(extra: str = "", **scene: object) -> Trace:
    data = (AXIS + extra + "Ende\n").encode()
    return dry_run(data, "axis.lis", ScenarioInput(**{**SCENE, **scene})).trace


def drive_run(start: float, drive: dict[str, object]) -> Trace:
    scenario = ScenarioInput(
        start_position=start,
        cam=(40.0, 50.0),
        zero_pulse_period=5.0,
        zero_pulse_phase=1.0,
        limit_switches=(-100.0, 100.0),
        fixed_stop=30.0,
        drive=drive,
    )
    return dry_run(SERCOS_DRIVE, "drive.lis", scenario).trace


def test_a_cam_shorter_than_the_braking_distance_is_passed_through() -> None:
    # a_ref 125 mm/s²: braking from 100 mm/s takes 100² / 250 = 40 mm, the cam is 20 mm long. The edge at -100
    # is seen within one cycle (0.1 mm), so the axis stops near -140, past the cam's far end at -120.
    trace = run("getriebe[0].a_ref 125\n")
    assert trace.outcome == "failed"
    assert trace.failure == "the axis braked through the cam (braking distance 40 mm is longer than the cam)"
    assert [p.name for p in trace.phases] == ["to the reference cam"]
    assert -140.1 - 1e-9 <= trace.phases[0].end_position <= -140.0 + 1e-9


def test_a_limit_switch_on_the_cam_stops_the_move_off_it() -> None:
    # Starting on the cam, phase 2 moves positive off it, but the switch at -105 comes before the edge at -100.
    # The switch is 5 mm away: the axis reaches sqrt(2 · 500 · 5) = 70.7 mm/s there and brakes another 5 mm.
    trace = run(start_position=-110.0, limit_switches=(-1010.0, -105.0))
    assert trace.outcome == "failed"
    assert trace.failure == "off the reference cam: limit switch reached before the event was found"
    [phase] = trace.phases
    assert phase.ended_by == "limit switch reached" and approx(phase.end_position, -100.0, 1e-6)


def test_one_phase_homing_with_the_cam_behind_the_start_ends_at_the_limit_switch() -> None:
    trace = run("kenngr.ref_ohne_rev 1\n", start_position=-200.0)
    assert trace.outcome == "failed"
    assert [p.name for p in trace.phases] == ["to the reference cam"]
    assert trace.phases[0].ended_by == "limit switch reached"
    assert trace.reference is None


def test_a_fixed_stop_before_torq_min_distance_is_not_detected() -> None:
    # torq_min_distance 25 mm; the stop lies 20 mm away: the axis is blocked before detection is armed.
    text = ("kenngr.antr_typ 2\n" + TORQ + "kenngr.homing.torq_min_distance 250000\nEnde\n").encode()
    trace = dry_run(text, "torq.lis", ScenarioInput(start_position=0.0, fixed_stop=20.0)).trace
    assert trace.outcome == "failed"
    assert trace.failure == (
        "the stop lies within torq_min_distance: detection is not armed yet when the axis is blocked"
    )
    [phase] = trace.phases
    assert phase.ended_by == "blocked before torq_min_distance" and approx(phase.end_position, 20.0)
    # 5 mm/s at 50 mm/s²: t_acc 0.1 s, d_acc 0.25 mm; the stop after 0.1 + 19.75 / 5 = 4.05 s
    assert approx(phase.end_time, 4.05)


def test_a_simulated_drive_finds_its_stop_at_torq_distance_to_block() -> None:
    # simulation: the stop is torq_distance_to_block (12 mm) ahead of the start, whatever the scenario says
    text = ("kenngr.antr_typ 4\n" + TORQ + "kenngr.homing.torq_distance_to_block 120000\nEnde\n").encode()
    trace = dry_run(text, "sim.lis", ScenarioInput(start_position=3.0, fixed_stop=500.0)).trace
    assert trace.outcome == "homed", trace.failure
    assert trace.reference is not None and approx(trace.reference["position"], 15.0)
    assert trace.phases[0].ended_by == "the fixed stop was detected"


NC = {"method": "nc", "velocity": 20.0, "acceleration": 200.0, "reference_position": 0.0}


def test_nc_reference_modes_that_cannot_be_simulated_or_find_nothing() -> None:
    back = drive_run(80.0, {**NC, "reference_mode": "hardware-sync", "invert_sync_search": True})
    assert back.outcome == "failed" and back.failure == "a sync search back towards the cam is not simulated"
    no_latch = drive_run(80.0, {**NC, "reference_mode": "hardware-latch-pos"})
    assert no_latch.outcome == "failed"
    assert no_latch.failure == "no latch signal after the cam edge (scenario latch_position)"
    # the NC searches the cam negative: from 20 it runs away from the cam [40, 50] into the limit switch
    missed = drive_run(20.0, {**NC, "reference_mode": "plc-cam"})
    assert missed.outcome == "failed" and missed.phases[0].ended_by == "limit switch reached"


STANDARD = {
    "method": "standard",
    "velocity": 20.0,
    "acceleration": 200.0,
    "reference_position": 0.0,
    "first_search": {"trigger": "fixed_stop", "signed_max_distance": 80.0},
    "second_search": {"trigger": "limit_switch", "signed_max_distance": -10.0},
}


def test_drive_searches_for_a_fixed_stop_and_for_a_limit_switch() -> None:
    # first search positive to the fixed stop at 30 (found); second search negative for a limit switch, but
    # the switch at -100 is far more than 10 mm away: homing fails after 10 mm
    trace = drive_run(0.0, STANDARD)
    assert trace.outcome == "failed"
    assert trace.failure == "second search: no limit switch within 10 mm"
    assert [p.ended_by for p in trace.phases] == [
        "fixed stop found",
        "SignedMaxDistance travelled without a trigger",
    ]
    assert approx(trace.events[0].position, 30.0)
    # a cam search moving away from the cam finds nothing within its distance
    away = drive_run(0.0, {**STANDARD, "first_search": {"trigger": "cam", "signed_max_distance": -80.0}})
    assert away.failure == "first search: no cam within 80 mm"

"""The dry-run engine: hand-computed traces per strategy, and properties of every trace."""

from __future__ import annotations

import math
from collections import Counter

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from achslint.dryrun import dry_run, prepare, sweep
from achslint.homing.scenario import ScenarioInput
from achslint.output.dryrun import trace_json

from .conftest import examples
from .engine_scene import AXIS, SCENE, approx, drive_run, run


def test_three_phase_with_zero_pulse_by_hand():
    trace = run()
    # a = 500 mm/s², fast v = 100 mm/s: t_acc = 0.2 s, d_acc = 10 mm, braking 10 mm.
    # Phase 1: 0 -> cam edge -100 at t = 0.2 + (100 - 10)/100 = 1.1 s, brakes to -110 at 1.3 s.
    # Phase 2: back off at 100 mm/s: the edge -100 is 10 mm away = d_acc, reached at 0.2 s
    #          (t = 1.5 s, v = 100), brakes 10 mm to -90 at 1.7 s.
    # Phase 3: slow v = 10 mm/s: t_acc = 0.02 s, d_acc = 0.1 mm; edge after 10 mm at 0.02 + 9.9/10 = 1.01 s
    #          (t = 2.71 s); the pulse at -102.5 lies 2.5 mm further: t = 2.96 s; braking 0.1 mm -> -102.6 at 2.98 s.
    p1, p2, p3 = trace.phases
    assert (p1.direction, p2.direction, p3.direction) == ("negative", "positive", "negative")
    assert approx(p1.end_position, -110) and approx(p1.end_time, 1.3)
    assert approx(p2.end_position, -90) and approx(p2.end_time, 1.7)
    assert approx(p3.end_position, -102.6) and approx(p3.end_time, 2.98)
    assert trace.reference["kind"] == "zero pulse" and approx(trace.reference["position"], -102.5)
    assert approx(trace.reference["value"], -950.0)
    assert approx(trace.final_position, -950.1)  # stands 0.1 mm (braking) beyond the reference
    assert approx(trace.total_distance, 110 + 20 + 12.6)
    assert trace.outcome == "homed"


def test_slow_off_cam_and_start_on_the_cam():
    trace = run("kenngr.fast_from_cam 0\n", start_position=-110.0)
    # On the cam at the start: phase 1 skipped. Off the cam at 10 mm/s: the edge -100 is 10 mm away,
    # t = 0.02 + 9.9/10 = 1.01 s; braking 0.1 mm -> -99.9 at 1.03 s. Then back to the edge and to the pulse.
    assert [p.name for p in trace.phases] == ["off the reference cam", "onto the cam and reference"]
    assert approx(trace.phases[0].end_position, -99.9)
    assert approx(trace.phases[0].end_time, 1.03)
    assert approx(trace.reference["position"], -102.5)


def test_cam_edge_without_zero_pulse_is_sampled():
    trace = run("kenngr.homing_without_zero_pulse 1\n", start_position=0.3)
    # Phase 3 starts at -89.7 (start shifted by 0.3 mm); the edge -100 is 10.3 mm away: t = 0.02 + 10.2/10 = 1.04 s
    # after the phase start (1.7 s) -> 2.74 s, exactly on a cycle -> position -100 exactly.
    assert trace.reference["kind"] == "cam edge"
    assert trace.reference["position"] == pytest.approx(-100.0, abs=10 * 0.001 + 1e-9)  # error ≤ v·T
    sampled = run("kenngr.homing_without_zero_pulse 1\n", start_position=0.00037)
    assert 0 <= -100.0 - sampled.reference["position"] <= 10 * 0.001 + 1e-9


def test_sampled_zero_pulse_error_is_at_most_v_times_t():
    latched = run(start_position=0.0004)
    sampled = run(start_position=0.0004, hardware_latch=False)
    assert approx(latched.reference["position"], -102.5)
    assert 0 < -102.5 - sampled.reference["position"] <= 10 * 0.001 + 1e-9


def test_delayed_zero_pulse_activation():
    # Cam detected at -100; with a 3 mm shift the logic starts at -103, so the pulse at -102.5 is skipped
    # and the next one, at -107.5, is taken.
    trace = run("kenngr.shift_offset_zero_pulse_activation 30000\n")
    assert approx(trace.reference["position"], -107.5)


def test_falling_edge_variant():
    # cam_level 0: "active" outside the cam. Moving negative from -110 (inside the cam = inactive) the
    # active region starts at -120.
    trace = run("lr_hw[0].cam_level 0\n", start_position=-110.0)
    assert trace.phases[0].name == "to the reference cam"
    assert trace.events[0].kind == "cam reached" and approx(trace.events[0].position, -120.0)


def test_zero_pulse_only_and_one_phase():
    trace = run("kenngr.ref_ohne_nocken 1\nkenngr.ref_ohne_rev 1\n", zero_pulse_phase=-2.5)
    # One phase at 10 mm/s to the first pulse at -2.5: braking 0.1 mm.
    assert len(trace.phases) == 1 and approx(trace.reference["position"], -2.5)
    assert approx(trace.phases[0].end_position, -2.6)
    one_phase = run("kenngr.ref_ohne_rev 1\n", start_position=-110.0)
    assert any(w["code"] == "LIS402" for w in one_phase.warnings)  # started on the cam


def test_a_cam_shorter_than_the_braking_distance_is_passed_through():
    # a_ref 125 mm/s²: braking from 100 mm/s takes 100² / 250 = 40 mm, the cam is 20 mm long. The edge at -100
    # is seen within one cycle (0.1 mm), so the axis stops near -140, past the cam's far end at -120.
    trace = run("getriebe[0].a_ref 125\n")
    assert trace.outcome == "failed"
    assert trace.failure == "the axis braked through the cam (braking distance 40 mm is longer than the cam)"
    assert [p.name for p in trace.phases] == ["to the reference cam"]
    assert -140.1 - 1e-9 <= trace.phases[0].end_position <= -140.0 + 1e-9


def test_a_limit_switch_on_the_cam_stops_the_move_off_it():
    # Starting on the cam, phase 2 moves positive off it, but the switch at -105 comes before the edge at -100.
    # The switch is 5 mm away: the axis reaches sqrt(2 · 500 · 5) = 70.7 mm/s there and brakes another 5 mm.
    trace = run(start_position=-110.0, limit_switches=(-1010.0, -105.0))
    assert trace.outcome == "failed"
    # The failure names the switch and what it searched for beyond it: the cam's end at -100 (issue 26 item 11).
    assert trace.failure == (
        "off the reference cam: the limit switch at -105 mm was reached before the end of the cam at -100 mm"
    )
    [phase] = trace.phases
    assert phase.ended_by == "limit switch reached" and approx(phase.end_position, -100.0, 1e-6)


# --- one-phase homing on the cam and the zero pulse (TF5200 homing §2.3.3.2, §2.6, P-AXIS-00494) ------------
# The zero-pulse logic is armed where the cam is detected (plus shift_offset_zero_pulse_activation), whatever
# the speed: the first pulse after that point is the reference, also while the axis brakes after the cam.
# AXIS, one phase: cam edge -100 reached at 100 mm/s, detected at t = 0.2 + 90/100 = 1.1 s (a whole cycle,
# so exactly at -100); braking at 500 mm/s² takes 100/500 = 0.2 s and 100²/1000 = 10 mm: standstill at -110
# at 1.3 s. While braking from the cam, x = -100 - (100 τ - 250 τ²) and v = 100 - 500 τ (τ after 1.1 s).
ONE_PHASE = "kenngr.ref_ohne_rev 1\n"


def event_at(trace, prefix):
    return next(e for e in trace.events if e.kind.startswith(prefix))


def test_one_phase_takes_the_pulse_passed_while_braking():
    trace = run(ONE_PHASE)
    # Armed at -100; the first pulse after it is -102.5, 2.5 mm into the braking: v² = 100² - 2·500·2.5 = 7500,
    # v = 86.6025 mm/s, τ = (100 - 86.6025)/500 = 0.0267949 s. The axis brakes on to -110 (1.3 s): it stands
    # 7.5 mm beyond the reference, so the final position is -950 - 7.5 = -957.5. No second phase is needed.
    assert [p.name for p in trace.phases] == ["to the reference cam"]
    assert "zero pulse was detected while braking" in trace.phases[0].ended_by
    armed = event_at(trace, "cam reached, zero-pulse logic armed")
    assert approx(armed.position, -100.0) and approx(armed.time, 1.1)
    assert trace.reference["kind"] == "zero pulse" and approx(trace.reference["position"], -102.5)
    assert approx(trace.reference["speed"], math.sqrt(7500))
    assert approx(trace.events[-1].time, 1.1 + (100 - math.sqrt(7500)) / 500)
    assert approx(trace.phases[0].end_position, -110.0) and approx(trace.phases[0].end_time, 1.3)
    assert approx(trace.final_position, -957.5)


def test_one_phase_with_a_shift_arms_the_logic_past_the_cam_edge():
    trace = run(ONE_PHASE + "kenngr.shift_offset_zero_pulse_activation 30000\n")
    # Shift 3 mm (30000 × 0.1 µm): armed at -100 - 3 = -103, passed while braking: v² = 10000 - 1000·3 = 7000,
    # τ = (100 - 83.666)/500 = 0.032668 s. The pulse -102.5 lies before it; the next, -107.5, 7.5 mm after the
    # cam: v² = 10000 - 7500 = 2500, v = 50 mm/s at τ = 0.1 s (t = 1.2 s). Stands at -110: final -950 - 2.5.
    cam = event_at(trace, "cam reached")
    assert cam.kind == "cam reached" and approx(cam.position, -100.0) and approx(cam.time, 1.1)
    armed = event_at(trace, "zero-pulse logic armed")
    assert approx(armed.position, -103.0) and approx(armed.time, 1.1 + (100 - math.sqrt(7000)) / 500)
    assert approx(trace.reference["position"], -107.5) and approx(trace.reference["speed"], 50.0)
    assert approx(trace.events[-1].time, 1.2)
    assert approx(trace.final_position, -952.5)
    assert [e.kind for e in trace.events] == [cam.kind, armed.kind, "zero pulse"]


def test_one_phase_without_latch_samples_the_pulse_while_braking():
    trace = run(ONE_PHASE, hardware_latch=False)
    # The pulse -102.5 is crossed at 1.1267949 s and seen at the next cycle, 1.127 s (τ = 0.027 s):
    # x = -100 - (100·0.027 - 250·0.027²) = -102.51775, v = 100 - 500·0.027 = 86.5 mm/s (error ≤ v·T).
    assert approx(trace.reference["position"], -102.51775)
    assert approx(trace.reference["speed"], 86.5) and approx(trace.events[-1].time, 1.127)
    assert approx(trace.final_position, -950.0 + (-110.0 + 102.51775))


def test_one_phase_armed_beyond_the_standstill_searches_on_at_vb_reflow():
    trace = run(ONE_PHASE + "kenngr.shift_offset_zero_pulse_activation 120000\n")
    # Shift 12 mm: armed at -112, beyond the standstill at -110. Phase 2 starts there at 10 mm/s (ramp 0.02 s,
    # 0.1 mm): it passes -112 after 0.02 + 1.9/10 = 0.21 s (1.51 s) and reaches the next pulse -112.5 after
    # 0.02 + 2.4/10 = 0.26 s (1.56 s), then brakes 0.1 mm to -112.6 (1.58 s).
    assert [p.name for p in trace.phases] == ["to the reference cam", "on to the reference"]
    armed = event_at(trace, "zero-pulse logic armed")
    assert approx(armed.position, -112.0) and approx(armed.time, 1.51)
    assert approx(trace.reference["position"], -112.5) and approx(trace.events[-1].time, 1.56)
    assert approx(trace.phases[-1].end_position, -112.6) and approx(trace.phases[-1].end_time, 1.58)
    assert approx(trace.final_position, -950.1)


def test_one_phase_pulse_after_the_standstill():
    trace = run(ONE_PHASE, zero_pulse_period=20.0, zero_pulse_phase=-112.0)
    # Pulses every 20 mm at -112: the first after the arming point -100 lies 2 mm past the standstill at -110.
    # Phase 2 from -110 at 10 mm/s reaches it after 0.02 + 1.9/10 = 0.21 s (1.51 s) and stands 0.1 mm beyond.
    assert approx(trace.reference["position"], -112.0) and approx(trace.events[-1].time, 1.51)
    assert approx(trace.reference["speed"], 10.0) and approx(trace.final_position, -950.1)


def test_one_phase_search_limit_reached_while_braking():
    trace = run(ONE_PHASE + "lr_hw[0].zero_pulse_search_max_dist 10000\n")
    # 1 mm of search from the arming point -100, but the pulse -102.5 is 2.5 mm away: the limit (-101) is
    # passed while braking, homing fails and the axis stands at -110.
    assert trace.outcome == "failed" and trace.reference is None
    assert "zero_pulse_search_max_dist" in trace.phases[-1].ended_by
    assert approx(trace.phases[-1].end_position, -110.0)


def test_one_phase_homing_with_the_cam_behind_the_start_ends_at_the_limit_switch():
    trace = run(ONE_PHASE, start_position=-200.0)
    assert trace.outcome == "failed"
    assert [p.name for p in trace.phases] == ["to the reference cam"]
    assert trace.phases[0].ended_by == "limit switch reached"
    assert trace.reference is None


def test_explain_and_dry_run_agree_on_where_one_phase_homing_arms_the_logic():
    from achslint.explanation import explain_list

    text = (AXIS + ONE_PHASE + "kenngr.shift_offset_zero_pulse_activation 30000\nEnde\n").encode()
    phases = explain_list(text, "axis.lis")["phases"]
    # explain: the logic is armed 3 mm after the cam edge, and a pulse passed while braking is the reference;
    # the dry-run arms it 3 mm after the cam was detected (-100) and takes the pulse -107.5 while braking.
    assert "the zero-pulse logic is armed 3 mm after the cam edge" in phases[0]["ends_when"]
    assert "passed while the axis still brakes after the cam is the reference" in phases[1]["ends_when"]
    trace = run(ONE_PHASE + "kenngr.shift_offset_zero_pulse_activation 30000\n")
    assert approx(event_at(trace, "cam reached").position, -100.0)
    assert approx(event_at(trace, "zero-pulse logic armed").position, -103.0)
    assert len(trace.phases) == 1 and "while braking" in trace.phases[0].ended_by


def test_missed_cam_fails_cleanly_at_the_limit_switch():
    trace = run(start_position=-200.0)  # behind the cam in the homing direction
    assert trace.outcome == "failed"
    assert trace.phases[-1].ended_by == "limit switch reached"
    # The cam [-120, -100] lies behind the start: nothing ahead in the homing direction (issue 26 item 11).
    assert trace.failure == (
        "to the reference cam: the limit switch at -1010 mm was reached before the cam, which lies nowhere "
        "ahead in the negative direction"
    )
    assert trace.phases[-1].end_position <= -1010.0


def test_zero_pulse_search_is_bounded():
    trace = run(
        "lr_hw[0].zero_pulse_search_max_dist 10000\n", zero_pulse_phase=-104.0, zero_pulse_period=50.0
    )
    # The pulse lies 4 mm behind the cam edge but only 1 mm of search is allowed.
    assert trace.outcome == "failed" and "maximum search distance" in trace.phases[-1].ended_by


def test_simulated_drive():
    trace = dry_run(
        b"kenngr.antr_typ 4\nkenngr.ref_richt 1\nantr.simu.rpf_weg_bis_nip 200\n"
        b"getriebe[0].vb_reflow 2000\ngetriebe[0].a_ref 100\nEnde\n",
        "sim.lis",
    ).trace
    # 200 × 0.1 µm = 0.02 mm at 2 mm/s (t_acc 0.02 s, d_acc 0.02 mm): reached at exactly the end of the ramp.
    assert trace.strategy.id == "simulation"
    assert approx(trace.reference["position"], 0.02)
    assert approx(trace.phases[0].end_position, 0.02 + 0.02)


def test_fixed_stop_by_hand():
    text = (
        b"kenngr.antr_typ 2\nkenngr.homing.homing_type TORQ\nkenngr.homing.torq_homing_dir POSITIVE\n"
        b"antr.fixed_stop.drive_ident[0].id TORQUE_LIMIT\n"  # required for the move (P-AXIS-00719, LIS328)
        b"getriebe[0].homing.torq_move_velocity 5000\ngetriebe[0].homing.torq_move_acceleration 50\n"
        b"kenngr.homing.torq_max_distance 2000000\nkenngr.homing.torq_detect_time 25000\n"
        b"kenngr.homing.torq_retraction_distance 50000\nkenngr.homing.torq_homing_position 100000\nEnde\n"
    )
    trace = dry_run(text, "torq.lis", ScenarioInput(start_position=0.0, fixed_stop=20.0)).trace
    # 5 mm/s at 50 mm/s²: t_acc 0.1 s, d_acc 0.25 mm; stop at 20 mm after 0.1 + 19.75/5 = 4.05 s;
    # detected 25 ms later; value 10 mm; retract 5 mm (5 mm/s, 0.1 s ramps): final 10 - 5 = 5 mm.
    assert approx(trace.events[0].time, 4.05)
    assert approx(trace.phases[0].end_time, 4.075)
    assert approx(trace.reference["value"], 10.0)
    assert approx(trace.final_position, 5.0)
    assert approx(trace.phases[1].end_time, 4.075 + 0.1 + 0.9 + 0.1)
    missing = dry_run(text, "torq.lis", ScenarioInput(start_position=0.0, fixed_stop=300.0)).trace
    assert missing.outcome == "failed" and "torq_max_distance" in missing.failure


def test_fixed_stop_without_a_stop_in_the_scenario_aborts_after_the_maximum_distance():
    # A Scenario built in Python may have no fixed stop at all: the move ends at torq_max_distance
    # (2000000 x 0.1 µm = 200 mm), as when the stop lies beyond it (it raised a TypeError before).
    text = (
        b"kenngr.antr_typ 2\nkenngr.homing.homing_type TORQ\nkenngr.homing.torq_homing_dir POSITIVE\n"
        b"antr.fixed_stop.drive_ident[0].id TORQUE_LIMIT\n"  # required for the move (P-AXIS-00719, LIS328)
        b"getriebe[0].homing.torq_move_velocity 5000\ngetriebe[0].homing.torq_move_acceleration 50\n"
        b"kenngr.homing.torq_max_distance 2000000\nEnde\n"
    )
    simulator = prepare(text, "torq.lis", ScenarioInput(start_position=0.0))
    simulator.scenario.fixed_stop = None
    trace = simulator.run()
    assert trace.outcome == "failed" and "torq_max_distance" in (trace.failure or "")
    assert approx(trace.phases[0].end_position, 200.0 + 0.25)  # braking from 5 mm/s at 50 mm/s²: 0.25 mm


TORQ = (
    "kenngr.homing.homing_type TORQ\nkenngr.homing.torq_homing_dir POSITIVE\n"
    "getriebe[0].homing.torq_move_velocity 5000\ngetriebe[0].homing.torq_move_acceleration 50\n"
    "kenngr.homing.torq_detect_time 25000\nantr.fixed_stop.drive_ident[0].id TORQUE_LIMIT\n"
)


def test_a_fixed_stop_before_torq_min_distance_is_not_detected():
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


def test_a_simulated_drive_finds_its_stop_at_torq_distance_to_block():
    # simulation: the stop is torq_distance_to_block (12 mm) ahead of the start, whatever the scenario says
    text = ("kenngr.antr_typ 4\n" + TORQ + "kenngr.homing.torq_distance_to_block 120000\nEnde\n").encode()
    trace = dry_run(text, "sim.lis", ScenarioInput(start_position=3.0, fixed_stop=500.0)).trace
    assert trace.outcome == "homed", trace.failure
    assert trace.reference is not None and approx(trace.reference["position"], 15.0)
    assert trace.phases[0].ended_by == "the fixed stop was detected"


def test_absolute_and_disabled_axes_do_not_move():
    assert dry_run(b"kenngr.abs_pos_gueltig 1\nEnde\n", "a.lis").trace.outcome == "not_required"
    disabled = dry_run(b"kenngr.homing.homing_type DISABLED\nEnde\n", "d.lis").trace
    assert disabled.outcome == "failed" and not disabled.phases


def test_lis405_zero_pulse_close_to_the_cam_edge():
    close = run(zero_pulse_phase=-100.005, cam_jitter=0.02)
    warning = next(w for w in close.warnings if w["code"] == "LIS405")
    # Armed at -100, pulse 0.005 mm later: margin 10 mm/s × 1 ms + 0.02 = 0.03 mm. Half a revolution (2.5 mm)
    # is reached with a shift of 0.005 - 2.5 + 5 = 2.505 mm = 25050 × 0.1 µm.
    assert "25050" in warning["message"]
    assert not any(w["code"] == "LIS405" for w in run().warnings)


def lis405(trace):
    return next((w["message"] for w in trace.warnings if w["code"] == "LIS405"), None)


def test_lis405_in_one_phase_homing_as_in_three_phase_homing():
    # Pulses every 4 mm at -100.01: 0.01 mm after the cam edge -100 where the logic is armed (§2.6), well
    # within the cam jitter (0.02 mm). Three phases: margin 10 mm/s × 1 ms + 0.02 = 0.03 mm. One phase takes
    # the cam at vb_refmax: margin 100 mm/s × 1 ms + 0.02 = 0.12 mm. Both warn.
    scene = dict(zero_pulse_period=4.0, zero_pulse_phase=-100.01, cam_jitter=0.02)
    three = lis405(run(**scene))
    one = lis405(run(ONE_PHASE, **scene))
    assert three is not None and one is not None
    assert "0.01 mm after" in one and "0.12 mm" in one and "0.03 mm" in three
    # The shift that puts the pulse half a revolution away: 0.01 - 2 + 4 = 2.01 mm = 20100 × 0.1 µm. Armed at
    # -102.01, the logic then takes -104.01 instead of -100.01: the reference moves 4 mm (one pulse period) in
    # the homing direction, so pos_refpkt -950 mm must become -954 mm = -9540000 × 0.1 µm.
    for message in (one, three):
        assert "to about 20100 (= 2.01 mm)" in message
        assert "4 mm (one zero-pulse period) in the homing direction" in message
        assert "getriebe[0].pos_refpkt by -4 mm, to about -9540000" in message
    shifted = run(ONE_PHASE + "kenngr.shift_offset_zero_pulse_activation 20100\n", **scene)
    assert lis405(shifted) is None and approx(shifted.reference["position"], -104.01)


def test_lis405_pulse_just_before_the_arming_point_keeps_the_reference():
    # A pulse 0.01 mm before the arming point (-99.99): the logic takes the next one, -103.99 (3.99 mm on),
    # unless the jitter arms it early. Shift (3.99 - 2) mod 4 = 1.99 mm -> armed at -101.99, still -103.99:
    # the reference does not move and pos_refpkt stays.
    message = lis405(run(ONE_PHASE, zero_pulse_period=4.0, zero_pulse_phase=-99.99, cam_jitter=0.02))
    assert message is not None and "0.01 mm before" in message and "to about 19900" in message
    assert "the reference stays on the same zero pulse" in message and "pos_refpkt keeps its value" in message


def test_sweep_of_one_phase_homing_counts_the_jumps_an_independent_model_predicts():
    # One phase (§2.3.3.2), latched pulses every 4 mm at -100.07: 0.07 mm after the cam edge -100. The cam is
    # approached at 100 mm/s and sampled every 1 ms, so the logic is armed between -100 and -100.1 depending on
    # the start: beyond -100.07 the pulse is missed and the next one, 4 mm on, is taken.
    import random

    scene = dict(
        zero_pulse_period=4.0, zero_pulse_phase=-100.07, cam_jitter=0.0, limit_switches=(-200.0, 200.0)
    )
    simulator = prepare(
        (AXIS + ONE_PHASE + "Ende\n").encode(), "axis.lis", ScenarioInput(**{**SCENE, **scene})
    )
    summary = sweep(simulator, 400, seed=11)

    # The independent model, closed form: from rest at x, accelerate at 500 mm/s² to 100 mm/s (0.2 s, 10 mm),
    # reach the edge after D = x + 100 mm, see it at the next whole millisecond, arm there; the reference is
    # the first pulse -100.07 - 4k at or beyond the arming point. Starting on the cam the logic is armed at the
    # start; below the cam the axis runs into the limit switch. The sweep draws its starts uniformly between
    # the limit switches with random.Random(seed) and, without cam jitter, nothing else.
    def expected_reference(x):
        if x < -120.0:
            return None
        arm = x
        if x > -100.0:
            distance = x + 100.0
            t = math.sqrt(distance / 250.0) if distance <= 10.0 else 0.2 + (distance - 10.0) / 100.0
            seen = math.ceil(t / 0.001 - 1e-9) * 0.001
            travelled = 250.0 * seen**2 if seen <= 0.2 else 10.0 + 100.0 * (seen - 0.2)
            arm = x - travelled
        return -100.07 - 4.0 * math.ceil((-100.07 - arm) / 4.0 - 1e-12)

    rng = random.Random(11)
    starts = [rng.uniform(-200.0, 200.0) for _ in range(400)]
    references = [r for r in map(expected_reference, starts) if r is not None]
    pulses = Counter(round((reference + 100.07) / 4.0) for reference in references)
    assert summary["outcomes"]["homed"] == len(references)
    assert summary["distinct_pulses"] == len(pulses)
    assert summary["one_revolution_jumps"] == len(references) - max(pulses.values())
    # Starts before the cam take -100.07 or, armed past it, -104.07; both occur in this sweep.
    before_cam = Counter(round(expected_reference(x), 6) for x in starts if x > -100.0)
    assert set(before_cam) == {-100.07, -104.07}
    assert summary["reference_max"] == pytest.approx(-100.07)


def test_sweep_reports_one_revolution_jumps():
    simulator = prepare(
        (AXIS + "Ende\n").encode(),
        "axis.lis",
        ScenarioInput(
            **{**SCENE, "zero_pulse_phase": -100.005, "cam_jitter": 0.02, "limit_switches": (-1010.0, 1010.0)}
        ),
    )
    summary = sweep(simulator, 300, seed=3)
    assert summary["runs"] == 300
    assert summary["distinct_pulses"] == 2 and summary["one_revolution_jumps"] > 0
    assert summary["spread"] == pytest.approx(5.0, abs=1e-6)
    steady = sweep(prepare((AXIS + "Ende\n").encode(), "axis.lis", ScenarioInput(**SCENE)), 300, seed=3)
    assert steady["distinct_pulses"] == 1 and steady["spread"] == pytest.approx(0.0, abs=1e-9)


def test_json_has_the_stable_keys():
    document = trace_json(dry_run((AXIS + "Ende\n").encode(), "axis.lis", ScenarioInput(**SCENE)))
    assert {
        "version",
        "axis",
        "strategy",
        "scenario",
        "phases",
        "events",
        "reference",
        "final_position",
        "total_time",
        "total_distance",
        "outcome",
        "warnings",
    } <= set(document)
    assert set(document["phases"][0]) == {
        "name",
        "direction",
        "velocity",
        "start_position",
        "end_position",
        "start_time",
        "end_time",
        "ended_by",
    }
    assert document["outcome"] == "homed"


# --- properties of every trace ---------------------------------------------------------------


@settings(max_examples=examples(150), deadline=None)
@given(
    start=st.floats(-400, 400),
    ref_richt=st.sampled_from(["0", "1"]),
    without_pulse=st.sampled_from(["0", "1"]),
    one_phase=st.sampled_from(["0", "1"]),
    fast=st.integers(1000, 300000),
    slow=st.integers(100, 1000),
    accel=st.integers(10, 5000),
    latch=st.booleans(),
    phase=st.floats(-50, 50),
)
def test_trace_properties(start, ref_richt, without_pulse, one_phase, fast, slow, accel, latch, phase):
    # a_max 5000 so that every a_ref drawn is used as written (above a_max the CNC lowers it, LIS325).
    axis = (
        f"kenngr.antr_typ 1\nkenngr.ref_richt {ref_richt}\nkenngr.homing_without_zero_pulse {without_pulse}\n"
        f"kenngr.ref_ohne_rev {one_phase}\ngetriebe[0].vb_refmax {fast}\ngetriebe[0].vb_reflow {slow}\n"
        f"getriebe[0].a_ref {accel}\ngetriebe[0].dynamik.a_max 5000\nEnde\n"
    ).encode()
    scenario = ScenarioInput(
        start_position=start,
        cam=(-20.0, 20.0),
        zero_pulse_period=3.0,
        zero_pulse_phase=phase,
        hardware_latch=latch,
        limit_switches=(-500.0, 500.0),
    )
    run = dry_run(axis, "p.lis", scenario)
    trace = run.trace
    # Phases are contiguous in time and position.
    for before, after in zip(trace.phases, trace.phases[1:], strict=False):
        assert math.isclose(before.end_time, after.start_time, abs_tol=1e-9)
        assert math.isclose(before.end_position, after.start_position, abs_tol=1e-9)
    # Segments are contiguous and each phase ends at rest.
    for phase_record in trace.phases:
        for first, second in zip(phase_record.segments, phase_record.segments[1:], strict=False):
            assert math.isclose(first.position(first.t1), second.x0, abs_tol=1e-6)
        last = phase_record.segments[-1]
        assert math.isclose(last.velocity(last.t1), 0.0, abs_tol=1e-9)
        assert math.isclose(last.position(last.t1), phase_record.end_position, abs_tol=1e-6)
        # No phase goes past the limit switches by more than its braking distance.
        braking = max(fast, slow) ** 2 * 1e-6 / (2 * accel)
        assert -500.0 - braking - 1e-6 <= phase_record.end_position <= 500.0 + braking + 1e-6
    if trace.outcome == "homed":
        # The final position is the reference value plus the braking distance from the speed at the
        # reference event (the referencing speed, or less when the event comes during the acceleration).
        # One-phase homing on the cam edge takes it at the approach speed vb_refmax; one-phase homing on the
        # zero pulse takes a pulse passed while braking from vb_refmax after the cam (§2.6), so up to vb_refmax.
        one_phase_pulse = trace.strategy.id == "one_phase_cam_zero_pulse"
        fastest = one_phase_pulse or trace.strategy.definition.reference_speed == "vb_refmax"
        reference_speed = max(fast, slow) if fastest else slow
        speed = trace.reference["speed"]
        assert speed <= reference_speed * 1e-3 + 1e-12
        braking = speed * speed / (2 * accel)
        assert math.isclose(
            abs(trace.final_position - trace.reference["value"]), braking, rel_tol=1e-6, abs_tol=1e-9
        )
    else:
        assert trace.failure


# --- drive-side homing (Triamec drive homing methods) -------------------------------------------

STANDARD = {
    "method": "standard",
    "velocity": 20.0,
    "acceleration": 200.0,
    "reference_position": 0.0,
    "home_position": 10.0,
    "relocate_distance": -2.0,
    "first_search": {"trigger": "cam", "signed_max_distance": 80.0},
    "second_search": {"trigger": "zero_pulse", "signed_max_distance": -10.0},
}


def test_drive_standard_method_by_hand():
    trace = drive_run(0.0, STANDARD)
    # v 20 mm/s, a 200 mm/s²: ramps of 0.1 s and 1 mm. First search + to the cam at 40: t = 0.1 + 39/20 = 2.05 s,
    # stops at 41. Relocate -2 mm -> 39 (triangular, 0.2 s). Second search - (sign of SignedMaxDistance,
    # pulses are no "active" state) to the pulse at 36: t = 0.1 + 2/20 = 0.2 s -> 2.55 s; stops at 35.
    # The reference 0 is set at 36, so the axis stands at -1 and moves to the home position 10 (11 mm).
    assert [p.name for p in trace.phases] == [
        "first search",
        "relocate",
        "second search",
        "move to home position",
    ]
    assert [p.direction for p in trace.phases] == ["positive", "negative", "negative", "positive"]
    assert approx(trace.events[0].time, 2.05) and approx(trace.events[0].position, 40.0)
    assert approx(trace.reference["position"], 36.0) and approx(trace.reference["value"], 0.0)
    assert approx(trace.final_position, 10.0)
    assert approx(trace.phases[-1].end_position, 46.0)


def test_drive_search_reverses_when_the_trigger_is_already_active():
    trace = drive_run(45.0, STANDARD)  # starts on the cam: the first search moves negative, off the cam
    assert trace.phases[0].direction == "negative"
    assert approx(trace.events[0].position, 40.0)


def test_drive_early_trigger_and_max_distance():
    early = drive_run(40.001, STANDARD)  # 0.001 mm from the edge: sqrt(2 · 0.001 / 200) = 3.2 ms < 5 ms
    assert early.outcome == "failed" and "early-trigger" in early.failure
    far = drive_run(-90.0, {**STANDARD, "first_search": {"trigger": "cam", "signed_max_distance": 50.0}})
    assert far.outcome == "failed" and "within 50" in far.failure


def test_drive_immediate_at_position_and_absolute_encoder():
    assert drive_run(3.0, {"method": "immediate"}).final_position == 3.0
    assert drive_run(3.0, {"method": "at-position", "reference_position": 7.5}).final_position == 7.5
    assert drive_run(3.0, {"method": "absolute-encoder", "encoder_offset": -1.25}).final_position == 1.75
    assert not drive_run(3.0, {"method": "immediate"}).phases


@pytest.mark.parametrize(
    "mode,extra,expected",
    [
        ("plc-cam", {}, 50.0),  # the falling edge itself (sampled)
        ("hardware-sync", {}, 51.0),  # next zero pulse after the edge (pulses at 1 + 5k)
        ("software-sync", {"reference_mask_period": 4.0}, 53.0),  # next mask overflow (1 + 4k) after 50
        ("hardware-latch-pos", {"latch_position": 52.5}, 52.5),
    ],
)
def test_nc_reference_modes(mode, extra, expected):
    # Cam [40, 50]; the NC searches the cam negative by default, so starting at 80 it reaches 50 first,
    # stops on the cam, then moves positive off the falling edge at 50 and on to the mode's event.
    drive = {
        "method": "nc",
        "velocity": 20.0,
        "acceleration": 200.0,
        "reference_mode": mode,
        "reference_position": 0.0,
        **extra,
    }
    trace = drive_run(80.0, drive)
    assert trace.outcome == "homed", trace.failure
    assert [p.direction for p in trace.phases] == ["negative", "positive"]
    tolerance = 20.0 * 0.001 + 1e-9 if mode == "plc-cam" else 1e-9  # the cam edge is sampled each cycle
    assert trace.reference["position"] == pytest.approx(expected, abs=tolerance)
    assert trace.reference["position"] >= expected - 1e-9


NC = {"method": "nc", "velocity": 20.0, "acceleration": 200.0, "reference_position": 0.0}


def test_nc_reference_modes_that_cannot_be_simulated_or_find_nothing():
    back = drive_run(
        80.0, {**NC, "reference_mode": "hardware-sync", "invert_sync_search": True}, fixed_stop=30.0
    )
    # A mode the simulator does not cover is "not simulated", not a failure (issue 26 item 11): exit 0, a note.
    assert back.outcome == "not_simulated" and back.failure is None
    assert (
        "the sync search back towards the cam (invert_sync_search) is not simulated"
        in back.warnings[0]["message"]
    )
    no_latch = drive_run(80.0, {**NC, "reference_mode": "hardware-latch-pos"}, fixed_stop=30.0)
    assert no_latch.outcome == "failed"
    assert no_latch.failure == "no latch signal after the cam edge (scenario latch_position)"
    # the NC searches the cam negative: from 20 it runs away from the cam [40, 50] into the limit switch
    missed = drive_run(20.0, {**NC, "reference_mode": "plc-cam"}, fixed_stop=30.0)
    assert missed.outcome == "failed" and missed.phases[0].ended_by == "limit switch reached"


STOP_THEN_SWITCH = {
    "method": "standard",
    "velocity": 20.0,
    "acceleration": 200.0,
    "reference_position": 0.0,
    "first_search": {"trigger": "fixed_stop", "signed_max_distance": 80.0},
    "second_search": {"trigger": "limit_switch", "signed_max_distance": -10.0},
}


def test_drive_searches_for_a_fixed_stop_and_for_a_limit_switch():
    # first search positive to the fixed stop at 30 (found); second search negative for a limit switch, but
    # the switch at -100 is far more than 10 mm away: homing fails after 10 mm
    trace = drive_run(0.0, STOP_THEN_SWITCH, fixed_stop=30.0)
    assert trace.outcome == "failed"
    assert trace.failure == "second search: no limit switch within 10 mm"
    assert [p.ended_by for p in trace.phases] == [
        "fixed stop found",
        "SignedMaxDistance travelled without a trigger",
    ]
    assert approx(trace.events[0].position, 30.0)
    # a cam search moving away from the cam finds nothing within its distance
    away = drive_run(
        0.0,
        {**STOP_THEN_SWITCH, "first_search": {"trigger": "cam", "signed_max_distance": -80.0}},
        fixed_stop=30.0,
    )
    assert away.failure == "first search: no cam within 80 mm"


def test_encoder_overflow_by_hand():
    # 2^10 increments × 0.1 µm (wegaufz = wegaufn = 1) = 0.1024 mm per overflow, lattice anchored at the
    # scenario's pulse position -102.5. Armed at the cam edge -100, moving negative: the next overflow is at
    # -102.5 + floor(2.5 / 0.1024) × 0.1024 = -102.5 + 24 × 0.1024 = -100.0424 (computed, not sampled).
    # Lightbus: encoder-overflow homing is not available on the conventional drive of the base list (P-ERR-110416).
    trace = run(
        "kenngr.antr_typ 5\nkenngr.homing_overflow_evaluation 1\nantr.encoder_bit_range 10\n",
        hardware_latch=False,
    )
    assert trace.reference["kind"] == "encoder overflow"
    assert approx(trace.reference["position"], -100.0424)


def test_spindle_flying_homing_in_degrees():
    spindle = (
        b"kenngr.antr_typ 1\nkenngr.achs_typ 4\nkenngr.achs_mode 0x4\nkenngr.ref_ohne_rev 1\n"
        b"kenngr.ref_ohne_nocken 1\nkenngr.ref_richt 1\ngetriebe[0].vb_reflow 36000\n"
        b"getriebe[0].lslope_profil.a_grenz_stufe_1 360\ngetriebe[0].lslope_profil.a_grenz_stufe_2 720\nEnde\n"
    )
    trace = dry_run(
        spindle,
        "s.lis",
        ScenarioInput(
            start_position=0.0, zero_pulse_period=360.0, zero_pulse_phase=90.0, hardware_latch=True
        ),
    ).trace
    # A spindle accelerates with its default ramps, min(a_grenz_stufe_1, a_grenz_stufe_2), not a_ref (§2.3.2.1).
    # 36 °/s at 360 °/s²: ramp 0.1 s over 1.8°; the pulse at 90° is reached at 0.1 + 88.2/36 = 2.55 s.
    # Flying homing does not stop (§2.3.2.1): the trace ends there, turning at 36 °/s, with the value pos_refpkt 0.
    assert trace.strategy.id == "spindle_flying_zero_pulse" and trace.unit == "deg"
    assert approx(trace.reference["position"], 90.0) and approx(trace.events[-1].time, 2.55)
    assert approx(trace.final_position, 0.0) and approx(trace.reference["speed"], 36.0)
    assert approx(trace.phases[-1].end_time, 2.55) and trace.ends_moving

"""Dry-run fidelity (issue 11): rotation and modulo, flying spindle homing, the CNC's corrections, distances as
the manual defines them, accelerations per strategy, refused scenarios, sweeps and the text table.

Every expected number is worked out by hand in the comments; ramps are trapezoidal: t_acc = v/a,
d_acc = v²/2a, and a sampled signal is seen at the next 1 ms cycle."""

from __future__ import annotations

import contextlib
import io
import json
import math
import tempfile
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from achslint.cli import main
from achslint.dryrun import DryRunRefused, dry_run, prepare, refusal, sweep
from achslint.homing.scenario import ScenarioError, ScenarioInput, parse_input
from achslint.output.dryrun import render, sweep_words, trace_json
from achslint.rules import registry

from .conftest import FIXTURES, examples
from .engine_scene import AXIS as SHARED_AXIS
from .engine_scene import SCENE, approx

X_AXIS = FIXTURES / "lists" / "achsmds1.lis"


# --- spindles: modulo and flying homing (§2.3.2.1) --------------------------------------------------

# A spindle homing positive at vb_reflow 36 °/s with its default ramps min(360, 720) = 360 °/s²:
# t_acc = 0.1 s, d_acc = 1.8°. One zero pulse per revolution, at 300° (= -60°), latched.
SPINDLE = (
    "kenngr.antr_typ 1\nkenngr.achs_typ 4\nkenngr.ref_ohne_rev 1\nkenngr.ref_ohne_nocken 0\n"
    "kenngr.ref_richt 1\ngetriebe[0].vb_reflow 36000\ngetriebe[0].a_ref 5000\n"
    "getriebe[0].lslope_profil.a_grenz_stufe_1 360\ngetriebe[0].lslope_profil.a_grenz_stufe_2 720\n"
)
SPINDLE_SCENE = {
    "cam": (-100.0, -80.0),
    "zero_pulse_period": 360.0,
    "zero_pulse_phase": 300.0,
    "hardware_latch": True,
}


def spindle(extra: str = "", **scene):
    return dry_run(
        (SPINDLE + extra + "Ende\n").encode(), "s.lis", ScenarioInput(**{**SPINDLE_SCENE, **scene})
    ).trace


def test_spindle_with_the_cam_behind_it_turns_round_to_it():
    trace = spindle(start_position=0.0)
    # The cam [-100, -80] is [260, 280] modulo 360: "behind" the start for a linear search, 260° ahead when turning.
    # The cam counts where it is left, at 280°: t = 0.1 + (280 - 1.8)/36 = 7.82778 s, seen at the 7.828 s cycle,
    # at 1.8 + 36 × 7.728 = 280.008°. The next zero pulse after that is at 300°: t = 0.1 + 298.2/36 = 8.38333 s.
    assert trace.strategy.id == "spindle_flying_cam" and trace.outcome == "homed", trace.failure
    assert trace.scenario.limit_switches is None  # no fictitious limit switches on a spindle
    armed = next(e for e in trace.events if e.kind.startswith("cam left"))
    assert approx(armed.time, 7.828) and approx(armed.position, 280.008, 1e-6)
    assert approx(trace.reference["position"], 300.0)
    assert approx(trace.phases[-1].end_time, 0.1 + 298.2 / 36)
    # Flying: no stop. The trace ends at the reference, still turning at vb_reflow; the spindle reads pos_refpkt 0.
    assert trace.ends_moving and approx(trace.reference["speed"], 36.0)
    last = trace.phases[-1].segments[-1]
    assert approx(last.velocity(last.t1), 36.0) and approx(trace.final_position, 0.0)
    # a_ref (5000) is for axis types T and R: the spindle used its default ramps.
    assert trace.acceleration == 360 and "default ramps" in trace.acceleration_source


def test_flying_homing_starting_on_the_cam_turns_until_it_is_left():
    trace = spindle(start_position=-90.0)
    # On the cam [-100, -80] at -90: turns positive until -80 (10°): t = 0.1 + 8.2/36 = 0.32778 s, seen at
    # 0.328 s at -90 + 1.8 + 36 × 0.228 = -79.992°. Next pulse: -60 (300 - 360), 30° from the start:
    # t = 0.1 + 28.2/36 = 0.88333 s. The reference position is reported modulo 360: 300°.
    assert trace.events[0].kind.startswith("on the cam at the start")
    armed = next(e for e in trace.events if e.kind.startswith("cam left"))
    assert approx(armed.position, -79.992, 1e-6)
    assert approx(trace.phases[-1].end_position, -60.0) and approx(trace.phases[-1].end_time, 0.1 + 28.2 / 36)
    assert approx(trace.reference["position"], 300.0)
    assert len(trace.phases) == 1 and trace.phases[0].direction == "positive"


def test_flying_homing_with_a_shifted_activation_takes_the_pulse_after_the_shift():
    # Cam left at 280.008 (as above); shift 30° (300000 × 0.0001°) arms the logic at 310.008, past the pulse at
    # 300: the next one is one revolution later, at 660 -> 300° modulo.
    trace = spindle("kenngr.shift_offset_zero_pulse_activation 300000\n", start_position=0.0)
    assert approx(trace.phases[-1].end_position, 660.0)
    assert approx(trace.reference["position"], 300.0)
    # zero_pulse_search_max_dist counts from the activation point: 660 - 310.008 = 349.992° of search.
    bounded = spindle(
        "kenngr.shift_offset_zero_pulse_activation 300000\nlr_hw[0].zero_pulse_search_max_dist 3500000\n",
        start_position=0.0,
    )
    assert bounded.outcome == "homed"  # 349.992 <= 350
    short = spindle(
        "kenngr.shift_offset_zero_pulse_activation 300000\nlr_hw[0].zero_pulse_search_max_dist 3400000\n",
        start_position=0.0,
    )
    assert short.outcome == "failed" and "zero_pulse_search_max_dist" in short.failure


def test_flying_homing_arming_event_and_lis405_on_a_spindle():
    # Cam left at 280.008° (as above), shift 10° (100000 × 0.0001°): the logic is armed at 290.008°, passed at
    # t = 0.1 + (290.008 - 1.8)/36 = 8.1058 s. Events give both positions (§2.6).
    trace = spindle("kenngr.shift_offset_zero_pulse_activation 100000\n", start_position=0.0)
    left, armed = (e for e in trace.events if e.kind.startswith(("cam left", "zero-pulse logic armed")))
    assert left.kind == "cam left" and approx(left.position, 280.008, 1e-6)
    assert approx(armed.position, 290.008, 1e-6) and approx(armed.time, 0.1 + 288.208 / 36, 1e-6)
    # A pulse 0.012° after the arming point 280.008 with a cam jitter of 0.05°: margin 36 °/s × 1 ms + 0.05 =
    # 0.086° (LIS405). The shift of half a revolution, 180.012°, moves the reference by one pulse period, 360°:
    # the same angle on a spindle, so pos_refpkt stays.
    message = next(
        w["message"]
        for w in spindle(start_position=0.0, zero_pulse_phase=280.02, cam_jitter=0.05).warnings
        if w["code"] == "LIS405"
    )
    assert "0.012 ° after" in message and "to about 1800120" in message
    assert "whole revolutions only, to the same position within [0, 360) °" in message


def test_spindle_against_its_preferred_direction_is_refused_like_lint():
    body = (SPINDLE + "kenngr.vorz_richtung 1\nkenngr.beweg_richt 0\nEnde\n").encode()  # restricted, negative
    with pytest.raises(DryRunRefused, match="LIS319"):
        dry_run(body, "s.lis", ScenarioInput(**SPINDLE_SCENE))


# A modulo rotary axis (achs_typ 2, MODULO 0x4): 100 °/s to the cam, 10 °/s to the reference, a_ref 500 °/s².
ROTARY = (
    "kenngr.antr_typ 1\nkenngr.achs_typ 2\nkenngr.achs_mode 0x4\nkenngr.ref_richt 0\nkenngr.fast_from_cam 1\n"
    "getriebe[0].vb_refmax 100000\ngetriebe[0].vb_reflow 10000\ngetriebe[0].a_ref 500\n"
)


def rotary(extra: str = "", **scene):
    base = {
        "start_position": 0.0,
        "cam": (-345.0, -325.0),
        "zero_pulse_period": 5.0,
        "zero_pulse_phase": -327.5,
        "hardware_latch": True,
    }
    return dry_run((ROTARY + extra + "Ende\n").encode(), "r.lis", ScenarioInput(**{**base, **scene})).trace


def test_rotary_axis_with_path_monitoring_equal_to_the_modulo_range_homes():
    trace = rotary("kenngr.homing_max_movement_dist 3600000\n")
    # Phase 1: to -325 at 0.2 + 315/100 = 3.35 s, brakes 10° to -335. Phase 2: off the cam at 100 °/s to -315.
    # Phase 3: at 10 °/s onto the cam and to the pulse at -327.5, stops at -327.6.
    # Path length 335 + 20 + 12.6 = 367.6° > 360°, but the largest displacement from the start is 335° < 360°:
    # the reference is found "within a distance from the homing start position" (§2.4.1) -> homed.
    assert trace.outcome == "homed", trace.failure
    assert trace.total_distance > 360.0
    assert approx(trace.phases[0].end_position, -335.0) and approx(trace.phases[-1].end_position, -327.6)
    # Positions are modulo 360: the reference -327.5 is 32.5°; standing 0.1° beyond pos_refpkt 0 is 359.9°.
    assert approx(trace.reference["position"], 32.5) and approx(trace.final_position, 359.9)
    # The LIS309 minimum (the modulo range) lets homing complete; 300° does not reach the cam edge at 325°.
    short = rotary("kenngr.homing_max_movement_dist 3000000\n")
    assert short.outcome == "failed" and "P-ERR-70394" in short.failure


def test_rotary_modulo_axis_reaches_a_cam_behind_it_without_limit_switches():
    # Cam [20, 40] but the axis starts at 45 and homes negative: it reaches 40 after 5°... and one at [380, 400]
    # is the same cam. Starting at 0 it finds the cam at -320 (= 40 modulo) 320° away, no limit switch on the way.
    trace = rotary(cam=(20.0, 40.0), zero_pulse_phase=37.5)
    assert trace.scenario.limit_switches is None
    assert trace.outcome == "homed"
    assert approx(trace.events[0].position, -320.0)  # phase 1: 0.2 + 310/100 = 3.3 s, exactly on a cycle
    assert approx(trace.reference["position"], 37.5)


# --- the CNC's corrections are what the simulation uses, and they show ---------------------------

# The axis of engine_scene without its pos_refpkt (so the reference value is the default 0), in its scene.
AXIS = SHARED_AXIS.replace("getriebe[0].pos_refpkt -9500000\n", "")


def linear(extra: str = "", **scene):
    return dry_run((AXIS + extra + "Ende\n").encode(), "axis.lis", ScenarioInput(**{**SCENE, **scene})).trace


def codes(trace) -> set:
    return {w["code"] for w in trace.warnings}


def test_overflow_offset_beyond_one_revolution_is_reset_to_zero():
    overflow = "kenngr.antr_typ 5\nkenngr.homing_overflow_evaluation 1\nantr.encoder_bit_range 10\n"
    # One overflow every 2^10 × 0.1 µm = 0.1024 mm. Offset 500 (0.05 mm, inside a revolution) shifts the lattice
    # to -102.45 + k × 0.1024; armed at -100 moving negative: k = floor(2.45 / 0.1024) = 23 -> -100.0948.
    inside = linear(overflow + "antr.encoder_overflow_offset 500\n", hardware_latch=False)
    assert approx(inside.reference["position"], -102.45 + 23 * 0.1024)
    # Offset 5000 (0.5 mm) is beyond 0.1024 mm: the CNC uses 0 (P-ERR-70310), so the overflow is the unshifted
    # one, -102.5 + 24 × 0.1024 = -100.0424, and the correction shows as a warning with its id.
    beyond = linear(overflow + "antr.encoder_overflow_offset 5000\n", hardware_latch=False)
    assert approx(beyond.reference["position"], -102.5 + 24 * 0.1024)
    assert "P-ERR-70310" in codes(beyond)


def test_overflow_without_bit_range_says_what_stands_in():
    trace = linear("kenngr.antr_typ 5\nkenngr.homing_overflow_evaluation 1\nantr.encoder_bit_range 0\n")
    warning = next(w for w in trace.warnings if "encoder_bit_range is 0" in w["message"])
    assert "zero_pulse_period (5 mm)" in warning["message"]


def test_speed_cap_is_simulated_and_reported():
    trace = linear("getriebe[0].vb_not_referenced 50000\n")
    # vb_refmax 100 mm/s is lowered to 50 mm/s (P-ERR-110421): t_acc 0.1 s, d_acc 2.5 mm; the cam edge -100 is
    # reached at 0.1 + 97.5/50 = 2.05 s.
    assert approx(trace.phases[0].velocity, 50.0)
    assert approx(trace.events[0].time, 2.05)
    assert {"P-ERR-110421", "P-ERR-110422"} - codes(trace) == {
        "P-ERR-110422"
    }  # vb_reflow 10 is below the cap


def test_homing_type_fallback_is_simulated_and_reported():
    trace = linear("kenngr.antr_typ 5\nkenngr.homing.homing_type DRIVE_CONTROLLED\n")
    # Lightbus homes CNC-controlled only: the CNC uses CNC_CONTROLLED (P-ERR-110384), the three phases run.
    assert trace.strategy.id == "cam_zero_pulse" and "P-ERR-110384" in codes(trace)
    assert approx(trace.reference["position"], -102.5)


def test_no_reference_signal_fails_with_the_reason():
    trace = linear("kenngr.ref_ohne_nocken 1\nkenngr.ref_ohne_rev 1\nkenngr.homing_without_zero_pulse 1\n")
    assert trace.outcome == "failed" and "LIS318" in trace.failure and not trace.phases
    assert trace.reference is None


# --- distances as the manual defines them ----------------------------------------------------------


def test_zero_pulse_search_counts_from_the_activation_point():
    # Cam edge at -100, shift 3 mm: armed at -103; the pulses are at -102.5 - 5k, so the next one is -107.5,
    # 4.5 mm after the activation (7.5 mm after the cam edge).
    shift = "kenngr.shift_offset_zero_pulse_activation 30000\n"
    homed = linear(shift + "lr_hw[0].zero_pulse_search_max_dist 50000\n")  # 5 mm >= 4.5 mm
    assert homed.outcome == "homed" and approx(homed.reference["position"], -107.5)
    # The events give both points as positions (§2.6): the cam edge -100 at 2.71 s (phase 3 from -90 at
    # 10 mm/s: 0.02 + 9.9/10 = 1.01 s after 1.7 s) and the arming point -103, 3 mm (0.3 s) later.
    edge, armed = (e for e in homed.events if e.kind.startswith(("cam edge", "zero-pulse logic armed")))
    assert edge.kind == "cam edge detected" and approx(edge.position, -100.0) and approx(edge.time, 2.71)
    assert approx(armed.position, -103.0) and approx(armed.time, 3.01)
    failed = linear(shift + "lr_hw[0].zero_pulse_search_max_dist 40000\n")  # 4 mm < 4.5 mm
    assert failed.outcome == "failed" and "zero_pulse_search_max_dist" in failed.phases[-1].ended_by


# --- accelerations per strategy --------------------------------------------------------------------


def test_acceleration_source_per_strategy():
    assert "a_ref" in linear().acceleration_source and linear().acceleration == 500
    torq = dry_run(
        b"kenngr.antr_typ 2\nkenngr.homing.homing_type TORQ\ngetriebe[0].a_ref 900\n"
        b"antr.fixed_stop.drive_ident[0].id TORQUE_LIMIT\n"
        b"getriebe[0].homing.torq_move_velocity 5000\ngetriebe[0].homing.torq_move_acceleration 50\n"
        b"kenngr.homing.torq_max_distance 2000000\nEnde\n",
        "t.lis",
        ScenarioInput(start_position=0.0, fixed_stop=-20.0),
    ).trace
    assert torq.acceleration == 50 and "torq_move_acceleration" in torq.acceleration_source
    drive = b"kenngr.antr_typ 2\nkenngr.homing.homing_type DRIVE_CONTROLLED\nEnde\n"
    without = dry_run(drive, "d.lis").trace
    assert without.acceleration is None and "drive" in without.acceleration_source
    document = trace_json(
        dry_run(drive, "d.lis", ScenarioInput(drive={"method": "immediate", "acceleration": 250.0}))
    )
    assert document["axis"]["acceleration"] == 250.0 and "drive" in document["axis"]["acceleration_source"]


# --- scenarios refused -----------------------------------------------------------------------------


@pytest.mark.parametrize(
    "data,needle",
    [
        ({"start_position": math.inf}, "finite"),
        ({"cam": [math.nan, -250.0]}, "finite"),
        ({"limit_switches": [-math.inf, math.inf]}, "finite"),
        ({"fixed_stop": math.nan}, "finite"),
        ({"cycle_time_ms": math.inf}, "finite"),
        ({"cycle_time_ms": 200.0}, "cycle_time_ms"),
        ({"start_position": 1e308}, "start_position"),
        ({"zero_pulse_period": 1e-300}, "zero_pulse_period"),
        ({"zero_pulse_period": 2.0, "cam_jitter": 2.0}, "cam_jitter"),
        (
            {
                "drive": {
                    "method": "standard",
                    "first_search": {"signed_max_distance": 5.0, "bogus": 1},
                    "second_search": {"signed_max_distance": 1.0},
                }
            },
            "signed_max_distance",
        ),
    ],
)
def test_unusable_scenarios_are_refused(data, needle):
    with pytest.raises(ScenarioError) as caught:
        parse_input(data, "s.toml")
    assert needle in str(caught.value) and "\n" not in str(caught.value)


def test_nested_unknown_key_lists_its_own_level():
    with pytest.raises(ScenarioError) as caught:
        parse_input(
            {
                "drive": {
                    "method": "standard",
                    "first_search": {"signed_max_distance": 5.0, "bogus": 1},
                    "second_search": {"signed_max_distance": 1.0},
                }
            }
        )
    message = str(caught.value)
    assert "unknown key `drive.first_search.bogus`" in message
    assert "trigger" in message and "start_position" not in message


def test_position_bound_depends_on_the_unit():
    # 2e6 is beyond ±1e6 mm on a linear axis but a plausible angle (±1e9°).
    with pytest.raises(ScenarioError, match="start_position"):
        linear(start_position=2e6, limit_switches=None)
    assert spindle(start_position=2e6).outcome == "homed"


def test_drive_table_on_a_cnc_controlled_axis_is_an_error():
    with pytest.raises(ScenarioError, match=r"\[drive\] table"):
        linear(drive={"method": "immediate"})


def test_torq_on_a_lightbus_drive_is_refused_with_the_lint_text():
    with pytest.raises(DryRunRefused, match=r"LIS306.*P-ERR-110371"):
        dry_run(b"kenngr.antr_typ 5\nkenngr.homing.homing_type TORQ\nEnde\n", "t.lis")


@pytest.mark.parametrize("code", [code for code, rule in registry().items() if rule.refuses_homing])
def test_a_rule_that_says_the_cnc_refuses_the_homing_refuses_the_dry_run(code):
    """The refusal comes from the rules marked CNC_REFUSES_HOMING, run by the lint engine: their bad fixture
    is refused with their finding, their good fixture is not."""
    folder = FIXTURES / "rules" / code
    refused = refusal((folder / "bad.lis").read_bytes(), "bad.lis")
    assert refused is not None and refused.startswith(
        f"bad.lis: dry-run refused, the CNC does not run this homing: {code} "
    )
    assert refusal((folder / "good.lis").read_bytes(), "good.lis") is None


def test_the_rules_that_refuse_the_homing_are_the_drive_type_the_spindle_direction_and_the_torque_limit():
    refusing = [code for code, rule in registry().items() if rule.refuses_homing]
    assert refusing == ["LIS306", "LIS319", "LIS328"]


def write(folder: Path, name: str, text: str) -> Path:
    path = folder / name
    path.write_text(text, encoding="utf-8")
    return path


def run_main(*args: str) -> tuple[int, str, str]:
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        code = main(list(args))
    return code, out.getvalue(), err.getvalue()


def test_cli_refusals_are_one_line_exit_2(tmp_path):
    torq = write(tmp_path, "torq.lis", "kenngr.antr_typ 5\nkenngr.homing.homing_type TORQ\nEnde\n")
    code, out, err = run_main("dry-run", str(torq))
    assert code == 2 and "LIS306" in err and err.count("\n") == 1 and not out
    scene = write(tmp_path, "s.toml", 'start_position = inf\n[drive]\nmethod = "immediate"\n')
    code, _, err = run_main("dry-run", str(X_AXIS), "--scenario", str(scene))
    assert code == 2 and "start_position" in err and "internal error" not in err and err.count("\n") == 1
    drive = write(tmp_path, "d.toml", '[drive]\nmethod = "immediate"\n')
    code, _, err = run_main("dry-run", str(X_AXIS), "--scenario", str(drive))
    assert code == 2 and "[drive] table" in err


def test_config_scenario_table_and_cycle_time_are_used(tmp_path):
    listing = write(tmp_path, "achsmds1.lis", X_AXIS.read_bytes().decode("latin-1"))
    write(
        tmp_path,
        "achslint.toml",
        "cycle-time-us = 2000\n[scenario]\nstart_position = 50.0\n"
        "cam = [-300.0, -250.0]\nzero_pulse_period = 4.0\nzero_pulse_phase = -251.0\n",
    )
    code, out, _ = run_main("dry-run", str(listing), "--format", "json")
    document = json.loads(out)
    assert code == 0 and document["scenario"]["cycle_time_ms"] == 2.0
    assert document["scenario"]["start_position"] == 50.0 and document["reference"]["position"] == -251.0
    assert "cam" not in document["scenario"]["assumed"]
    # The command line wins over the configuration; the configuration's table is validated like a file.
    code, out, _ = run_main("dry-run", str(listing), "--format", "json", "--zero-pulse-phase", "-253")
    assert json.loads(out)["reference"]["position"] == -253.0
    other = tmp_path / "other"
    other.mkdir()
    write(other, "achslint.toml", "[scenario]\nstart_position = nan\n")
    code, _, err = run_main("dry-run", str(write(other, "achsmds1.lis", listing.read_text())))
    assert code == 2 and "achslint.toml" in err and "start_position" in err


# --- sweeps ----------------------------------------------------------------------------------------


def test_sweep_counts_outcomes_with_reasons_and_notes_assumed_geometry():
    simulator = prepare((AXIS + "Ende\n").encode(), "axis.lis", ScenarioInput(**SCENE))
    summary = sweep(simulator, 200, seed=5)
    # Starts drawn uniformly in [-1010, 1010]; those below the cam (< -120) move away from it and hit -1010.
    failed = summary["outcomes"].get("failed", 0)
    assert failed and failed + summary["outcomes"]["homed"] == 200
    assert summary["reasons"] == [{"outcome": "failed", "reason": "limit switch reached", "count": failed}]
    assert summary["assumed_geometry"] == []
    words = sweep_words(summary)
    assert f"failed: limit switch reached ×{failed}" in words and "ASSUMED" not in words
    assumed = sweep(prepare((AXIS + "Ende\n").encode(), "axis.lis"), 50)
    assert "cam" in assumed["assumed_geometry"] and "ASSUMED geometry" in sweep_words(assumed)


def test_sweep_failures_exit_1_unless_allowed():
    args = (
        "dry-run",
        str(X_AXIS),
        "--sweep",
        "100",
        "--cam",
        "-120,-100",
        "--limit-switches",
        "-200,200",
        "--zero-pulse-period",
        "5",
        "--zero-pulse-phase",
        "-102.5",
        "--format",
        "json",
    )
    code, out, _ = run_main(*args)
    document = json.loads(out, parse_constant=_refuse)
    assert document["outcome"] == "homed" and document["sweep"]["outcomes"]["failed"] > 0 and code == 1
    assert run_main(*args, "--allow-failures")[0] == 0


def test_spindle_sweep_covers_one_revolution_and_always_homes():
    simulator = prepare((SPINDLE + "Ende\n").encode(), "s.lis", ScenarioInput(**SPINDLE_SCENE))
    summary = sweep(simulator, 100)
    assert summary["start_range"] == [0.0, 360.0] and summary["outcomes"] == {"homed": 100}
    assert summary["distinct_pulses"] == 1  # every start finds the same pulse modulo one revolution


# --- text output -----------------------------------------------------------------------------------


def _text(run, width=80) -> str:
    from rich.console import Console

    console = Console(width=width, record=True, no_color=True, highlight=False, file=io.StringIO())
    render(run, console)
    return console.export_text()


@pytest.mark.parametrize(
    "body",
    [
        (AXIS + "getriebe[0].vb_not_referenced 50000\nEnde\n").encode(),
        X_AXIS.read_bytes(),
        (SPINDLE + "Ende\n").encode(),
        b"kenngr.antr_typ 2\nkenngr.homing.homing_type DRIVE_CONTROLLED\nEnde\n",
    ],
)
def test_text_fits_80_columns_without_truncating_or_none(body):
    run = dry_run(
        body,
        "axis.lis",
        ScenarioInput(start_position=-37.123456, limit_switches=(-1234.5678, 1234.5678))
        if b"achs_typ 4" not in body
        else ScenarioInput(start_position=-37.123456),
    )
    text = _text(run)
    table_lines = [
        line
        for line in text.splitlines()
        if not line.startswith(("Scenario", "Assumed", "Homing acc", "CNC correction", "note", "LIS"))
    ]
    assert all(len(line) <= 80 for line in table_lines), max(table_lines, key=len)
    assert "…" not in text and "None" not in text
    for phase in run.trace.phases:
        assert f"{phase.end_position:.4f}".replace("-0.0000", "0.0000") in text  # whole numbers, never cut


# --- arbitrary numbers in every scenario field -----------------------------------------------------


def _refuse(constant):
    raise ValueError(f"non-standard JSON constant {constant}")


NUMBERS = st.one_of(
    st.floats(allow_nan=True, allow_infinity=True),
    st.sampled_from([0.0, -0.0, 1e-300, 5e-324, 1e308, -1e308, 1e6, 1e9 + 1, 0.04, 100.0, 1.0, -250.0]),
    st.floats(-1000, 1000),
)
FIELDS = [
    "start_position",
    "zero_pulse_period",
    "zero_pulse_phase",
    "cycle_time_ms",
    "fixed_stop",
    "cam_jitter",
]
PAIRS = ["cam", "limit_switches"]
DRIVE_NUMBERS = ["velocity", "acceleration", "reference_position", "home_position", "relocate_distance"]
LISTS = {
    "linear": X_AXIS.read_bytes(),
    "spindle": (SPINDLE + "Ende\n").encode(),
    "torq": b"kenngr.antr_typ 2\nkenngr.homing.homing_type TORQ\ngetriebe[0].homing.torq_move_velocity 5000\n"
    b"getriebe[0].homing.torq_move_acceleration 50\nkenngr.homing.torq_max_distance 2000000\nEnde\n",
    "drive": b"kenngr.antr_typ 2\nkenngr.homing.homing_type DRIVE_CONTROLLED\nEnde\n",
}


def _toml(value: float) -> str:
    return repr(float(value))  # nan, inf and -inf are TOML spellings too


@settings(max_examples=examples(60), deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    axis=st.sampled_from(sorted(LISTS)),
    scalars=st.dictionaries(st.sampled_from(FIELDS), NUMBERS, max_size=4),
    pairs=st.dictionaries(st.sampled_from(PAIRS), st.tuples(NUMBERS, NUMBERS), max_size=2),
    drive=st.one_of(st.none(), st.dictionaries(st.sampled_from(DRIVE_NUMBERS), NUMBERS, max_size=3)),
    sweep_runs=st.sampled_from([0, 5]),
)
def test_any_numbers_give_exit_0_1_2_and_strict_json(axis, scalars, pairs, drive, sweep_runs):
    lines = [f"{key} = {_toml(value)}" for key, value in scalars.items()]
    lines += [f"{key} = [{_toml(a)}, {_toml(b)}]" for key, (a, b) in pairs.items()]
    if drive is not None:
        lines += [
            "[drive]",
            'method = "standard"',
            *(f"{key} = {_toml(v)}" for key, v in drive.items()),
            "[drive.first_search]",
            'trigger = "cam"',
            "signed_max_distance = 80.0",
            "[drive.second_search]",
            'trigger = "zero_pulse"',
            "signed_max_distance = -10.0",
        ]
    with tempfile.TemporaryDirectory() as folder:
        listing = Path(folder) / "achsmds1.lis"
        listing.write_bytes(LISTS[axis])
        scene = write(Path(folder), "s.toml", "\n".join(lines) + "\n")
        code, out, err = run_main(
            "dry-run",
            str(listing),
            "--scenario",
            str(scene),
            "--format",
            "json",
            "--sweep",
            str(sweep_runs),
            "--allow-failures",
        )
    assert code in (0, 1, 2), err
    assert "internal error" not in err and "Traceback" not in err
    if code == 2:
        assert err.count("\n") == 1 and not out
    else:
        document = json.loads(out, parse_constant=_refuse)
        assert document["outcome"] in ("homed", "failed", "skipped", "not_required", "not_simulated")


# --- the plot ----------------------------------------------------------------------------------------


def test_plot_png_has_size_and_is_not_blank(tmp_path):
    matplotlib = pytest.importorskip("matplotlib")
    matplotlib.use("Agg")
    import matplotlib.image
    import numpy as np

    target = tmp_path / "homing.png"
    code, _, err = run_main(
        "dry-run", str(X_AXIS), "--start", "50", "--cam", "-300,-250", "--plot", str(target)
    )
    assert code == 0 and f"wrote {target}" in err
    pixels = matplotlib.image.imread(str(target))
    assert pixels.shape[0] == 750 and pixels.shape[1] == 1200  # 12 × 7.5 in at 100 dpi
    # Not blank: many distinct colours (curves, shades, markers), and not mostly one value. The colours are
    # told apart by numpy, each pixel's rounded channels as one value (a set of 128,000 tuples took 0.1 s).
    flat = np.ascontiguousarray(pixels.reshape(-1, pixels.shape[-1])[::7].round(2))
    colours = flat.view(np.dtype((np.void, flat.itemsize * flat.shape[1]))).ravel()
    assert len(np.unique(colours)) > 20
    assert target.read_bytes().startswith(b"\x89PNG")
    code, _, err = run_main("dry-run", str(X_AXIS), "--plot", str(tmp_path / "homing.svg"))
    assert code == 0 and b"<svg" in (tmp_path / "homing.svg").read_bytes()[:500]


def test_plot_series_reference_limits_and_failure():
    pytest.importorskip("matplotlib")
    from achslint.output.figures import build_figure

    trace = linear(
        "getriebe[0].pos_refpkt -9500000\nkenngr.swe_neg -10000000\nkenngr.swe_pos 10000000\n",
        zero_pulse_phase=-102.3,
    )
    figure = build_figure(trace)
    top = figure.axes[0]
    by_gid = {line.get_gid(): line for line in top.get_lines() if line.get_gid()}
    # The reference marker sits at the zero pulse -102.3 (scenario frame), the final square at -102.4 (braked 0.1).
    assert approx(by_gid["reference"].get_ydata()[0], -102.3)
    assert approx(by_gid["final"].get_ydata()[0], trace.phases[-1].end_position)
    # Limit switches ±1010 as lines; the software limits ±1000 (homed frame) lie at value - (−950 − (−102.3)).
    assert sorted(line.get_ydata()[0] for line in top.get_lines() if line.get_gid() == "limit switch") == [
        -1010,
        1010,
    ]
    soft = sorted(
        line.get_ydata()[0] for line in top.get_lines() if line.get_gid() == "software limit (after homing)"
    )
    assert approx(soft[0], -1000 + 950 - 102.3, 1e-6) and approx(soft[1], 1000 + 950 - 102.3, 1e-6)
    labels = [text.get_text() for text in top.get_legend().get_texts()]
    assert any("−102.3 mm → −950 mm" in label for label in labels)
    assert sum(label[:2] in ("1.", "2.", "3.") for label in labels) == 3  # every phase named in the legend
    assert len(figure.axes) == 3  # position, velocity and the zoom on the reference
    failed = build_figure(linear(start_position=-200.0))
    labels = [text.get_text() for text in failed.axes[0].get_legend().get_texts()]
    assert any(label.startswith("FAILED: ") and "limit switch" in label for label in labels)
    assert any(line.get_gid() == "failure" for line in failed.axes[0].get_lines())
    import matplotlib.pyplot as plt

    plt.close("all")

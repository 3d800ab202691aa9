"""Spindles homing from endless rotation (issue 26 item 3; TF5200 homing manual §2.3.2.1: "If the spindle executes
homing from endless rotation, it first accelerates or decelerates to the homing speed vb_reflow before being
referenced. The referencing direction is identical to the endless rotation direction."; §2.3.2: from endless
rotation only with ref_ohne_rev TRUE).

The spindle: vb_reflow 36 °/s (P-AXIS-00218), default ramps min(360, 720) = 360 °/s² (P-AXIS-00005/00006),
ref_richt positive, modulo [0, 360). The scene: the cam [260, 280] (every revolution), one zero pulse per
revolution at 300°, latched, 1 ms cycle. The referencing starts once the spindle runs at vb_reflow: a cam
edge or a pulse passed while the speed changes does not count (the tool's reading of "before")."""

from __future__ import annotations

import io
import math

import pytest
from rich.console import Console

from achslint.dryrun import dry_run
from achslint.explanation import explain_list
from achslint.homing.scenario import ScenarioError, ScenarioInput
from achslint.output.dryrun import render, trace_json

from .engine_scene import approx

SPINDLE = (
    "kenngr.antr_typ 1\nkenngr.achs_typ 4\nkenngr.achs_mode 0x4\nkenngr.ref_ohne_rev 1\nkenngr.ref_ohne_nocken 0\n"
    "kenngr.ref_richt 1\ngetriebe[0].vb_reflow 36000\n"
    "getriebe[0].lslope_profil.a_grenz_stufe_1 360\ngetriebe[0].lslope_profil.a_grenz_stufe_2 720\n"
)
SCENE = {"cam": (260.0, 280.0), "zero_pulse_period": 360.0, "zero_pulse_phase": 300.0, "hardware_latch": True}


def spin(extra: str = "", **scene):
    return dry_run(
        (SPINDLE + extra + "Ende\n").encode(),
        "s.lis",
        ScenarioInput(**{**SCENE, "start_position": 0.0, **scene}),
    )


def test_decelerating_from_720_deg_per_s():
    trace = spin(start_velocity=720.0).trace
    # 720 -> 36 °/s at 360 °/s²: t = 684/360 = 1.9 s, (720² - 36²)/(2·360) = 517104/720 = 718.2°. The cams passed
    # meanwhile (left at 280 and 640) do not count. From 718.2 (= 358.2 mod 360) the next cam starts at
    # 980 (= 260 + 720) and is left at 1000: t = 1.9 + 281.8/36 = 9.72778 s, seen at the 9.728 s cycle at
    # 718.2 + 36·7.828 = 1000.008°. The next pulse is 1020 (= 300): t = 1.9 + 301.8/36 = 10.28333 s.
    decelerate, fly = trace.phases
    assert decelerate.name == "decelerate to vb_reflow (from endless rotation)"
    assert approx(decelerate.end_time, 1.9) and approx(decelerate.end_position, 718.2, 1e-9)
    first = decelerate.segments[0]
    assert approx(first.v0, 720.0) and approx(first.a, -360.0)
    assert approx(fly.start_position, 718.2, 1e-9) and approx(fly.end_position, 1020.0, 1e-9)
    left = next(e for e in trace.events if e.kind.startswith("cam left"))
    assert approx(left.time, 9.728) and approx(left.position, 1000.008, 1e-9)
    assert trace.outcome == "homed" and trace.ends_moving
    assert approx(trace.reference["position"], 300.0, 1e-9) and approx(
        trace.reference["time"], 1.9 + 301.8 / 36
    )
    assert approx(trace.reference["speed"], 36.0)  # it keeps turning at vb_reflow
    assert approx(trace.cam_zero_pulse_offset, 19.992, 1e-9)  # 1020 - 1000.008
    kinds = [e.kind for e in trace.events]
    assert kinds[0] == "turning positive at 720 °/s (endless rotation): decelerates to vb_reflow"
    assert kinds[1] == "vb_reflow (36 °/s) reached: the referencing starts"


def test_accelerating_from_30_deg_per_s_in_the_rotation_direction():
    trace = spin(start_velocity=-30.0).trace
    # Turning negative at 30 °/s although ref_richt is positive: the rotation direction wins. 30 -> 36 °/s:
    # t = 6/360 = 1/60 s, (36² - 30²)/720 = 396/720 = 0.55°, so the referencing starts at -0.55°. Moving negative,
    # the cam [-100, -80] (= [260, 280]) is reached at -80 and left at -100: 0.55 + 79.45 + 20 = 100° from the
    # start, t = 1/60 + 99.45/36 = 2.77917 s, seen at the 2.780 s cycle at -(0.55 + 36·(2.780 - 1/60)) = -100.03°.
    # The next pulse going negative is -420 (= 300): t = 1/60 + 419.45/36 = 11.66806 s.
    accelerate, fly = trace.phases
    assert accelerate.name == "accelerate to vb_reflow (from endless rotation)"
    assert accelerate.direction == fly.direction == "negative"
    assert approx(accelerate.end_time, 1 / 60) and approx(accelerate.end_position, -0.55, 1e-9)
    left = next(e for e in trace.events if e.kind.startswith("cam left"))
    assert approx(left.time, 2.78) and approx(left.position, -100.03, 1e-9)
    assert approx(fly.end_position, -420.0, 1e-9) and approx(trace.reference["time"], 1 / 60 + 419.45 / 36)
    assert approx(trace.reference["position"], 300.0, 1e-9)
    assert approx(trace.cam_zero_pulse_offset, 319.97, 1e-9)  # 420 - 100.03


def test_turning_at_vb_reflow_already_references_without_a_speed_change():
    # Without a cam (ref_ohne_nocken 1) the zero-pulse logic is armed where the referencing starts: at the start,
    # since 36 °/s is vb_reflow. The pulse at 300° is 300° ahead: t = 300/36 = 8.3333 s, one phase only.
    trace = spin("kenngr.ref_ohne_nocken 1\n", start_velocity=36.0).trace
    assert [p.name for p in trace.phases] == ["reference on the fly"]
    assert trace.events[0].kind == "turning positive at 36 °/s = vb_reflow: the referencing starts"
    assert approx(trace.reference["time"], 300 / 36) and approx(trace.arming.armed, 0.0)


def test_standstill_is_unchanged_and_the_scenario_says_which():
    # From standstill (start_velocity 0, or not given and listed as assumed) the spindle accelerates from rest
    # in the homing direction: the cam left at 280.008 (test_dryrun_fidelity), the pulse at 300 at 8.38333 s.
    for run in (spin(start_velocity=0.0), spin()):
        trace = run.trace
        assert len(trace.phases) == 1 and approx(trace.reference["time"], 0.1 + 298.2 / 36)
    assert "start_velocity" in spin().trace.scenario.assumed
    assert "start_velocity" not in spin(start_velocity=0.0).trace.scenario.assumed
    document = trace_json(spin(start_velocity=720.0))
    assert document["scenario"]["start_velocity"] == 720.0
    console = Console(file=io.StringIO(), width=200, color_system=None)
    render(spin(start_velocity=720.0), console)
    assert (
        "Scenario: start 0 ° turning at +720 °/s (endless rotation), cam [260, 280]"
        in console.file.getvalue()
    )


def test_spindle_homing_with_reversal_cannot_start_from_rotation():
    # §2.3.2: "from endless rotation this can only be executed if the parameter ref_ohne_rev is set to TRUE.
    # Otherwise, an error message is output" (LIS320). No motion is simulated.
    trace = spin("kenngr.ref_ohne_rev 0\n", start_velocity=720.0).trace
    assert trace.outcome == "failed" and not trace.phases
    assert "from endless rotation the CNC homes only without reversal (ref_ohne_rev 1" in trace.failure
    assert "(LIS320)" in trace.failure


def test_only_a_spindle_turns_endlessly():
    with pytest.raises(ScenarioError, match="`start_velocity` \\(50\\) is for a spindle turning endlessly"):
        dry_run(b"kenngr.antr_typ 1\nEnde\n", "x.lis", ScenarioInput(start_velocity=50.0))


def test_explain_and_the_dry_run_agree_on_endless_rotation():
    # explain's phase note says the spindle keeps its direction and changes speed to vb_reflow first; the dry-run
    # has that phase and takes the reference only after it.
    [phase] = explain_list((SPINDLE + "Ende\n").encode(), "s.lis")["phases"]
    assert "From endless rotation" in phase["note"] and "keeps its rotation direction" in phase["note"]
    assert "first decelerates or accelerates to vb_reflow" in phase["note"]
    trace = spin(start_velocity=720.0).trace
    assert trace.phases[0].name.startswith("decelerate to vb_reflow")
    assert trace.reference["time"] > trace.phases[0].end_time
    # The speed change itself: v(t) = 720 - 360 t, reaching 36 at 1.9 s, and x(1.9) = 720·1.9 - 180·1.9² = 718.2.
    assert math.isclose(trace.phases[0].segments[0].position(1.9), 718.2)

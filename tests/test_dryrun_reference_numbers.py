"""The engineering numbers of the reference (issue 26 item 13): when the reference was taken, where the zero-pulse
logic was armed, and the offset from the reference cam to the zero pulse that the CNC reports after homing
(TF5200 homing manual §2.6: the CNC object "reference cam - zero pulse offset", read in the Geo task at index
group 0x20300). Every expected number is worked out by hand on the shared axis of engine_scene.py: fast
100 mm/s, slow 10 mm/s, 500 mm/s², homing negative, cam [-120, -100], a zero pulse every 5 mm at -102.5, latch."""

from __future__ import annotations

import io

from rich.console import Console

from achslint.dryrun import dry_run
from achslint.homing.scenario import ScenarioInput
from achslint.output.dryrun import render, trace_json

from .engine_scene import SCENE, approx, listed

SHIFT_3MM = "kenngr.shift_offset_zero_pulse_activation 30000\n"  # P-AXIS-00494, 30000 × 0.1 µm = 3 mm


def reference_json(extra: str = "", **scene):
    return trace_json(dry_run(listed(extra), "axis.lis", ScenarioInput(**{**SCENE, **scene})))["reference"]


def test_three_phase_reference_numbers():
    # Phase 3 starts at -90 at 1.7 s at 10 mm/s (ramp 0.02 s, 0.1 mm): the cam edge -100 after
    # 0.02 + 9.9/10 = 1.01 s (2.71 s, a whole cycle, so detected exactly at -100): the logic is armed there.
    # The pulse -102.5 is 2.5 mm on, at 2.71 + 0.25 = 2.96 s. Offset cam - zero pulse: 2.5 mm.
    reference = reference_json()
    assert reference["kind"] == "zero pulse"
    assert approx(reference["time"], 2.96) and approx(reference["armed_at"], -100.0)
    assert approx(reference["cam_zero_pulse_offset"], 2.5)


def test_the_offset_includes_the_shift_of_the_arming_point():
    # One phase (§2.3.3.2): cam detected at -100 (1.1 s); the 3 mm shift arms the logic at -103; the pulse
    # -102.5 lies before it, so -107.5 is the reference, passed while braking at τ = 0.1 s (100τ - 250τ² = 7.5):
    # t = 1.2 s. The offset the CNC reports counts from the cam: 107.5 - 100 = 7.5 mm (shift included).
    reference = reference_json("kenngr.ref_ohne_rev 1\n" + SHIFT_3MM)
    assert approx(reference["time"], 1.2) and approx(reference["armed_at"], -103.0)
    assert approx(reference["cam_zero_pulse_offset"], 7.5)
    # Three phases with the same shift: armed at -103 on the slow approach, the pulse -107.5 reached
    # 7.5 mm after the edge (2.71 + 0.75 = 3.46 s).
    three = reference_json(SHIFT_3MM)
    assert approx(three["time"], 3.46) and approx(three["armed_at"], -103.0)
    assert approx(three["cam_zero_pulse_offset"], 7.5)


def test_a_cam_edge_reference_and_a_zero_pulse_without_cam():
    # Without zero pulse (P-AXIS-00084) the cam edge is the reference: no zero-pulse logic, no offset.
    # Phase 3 reaches the edge -100 at 2.71 s (see above).
    edge = reference_json("kenngr.homing_without_zero_pulse 1\n")
    assert edge["kind"] == "cam edge" and approx(edge["time"], 2.71)
    assert edge["armed_at"] is None and edge["cam_zero_pulse_offset"] is None
    # Zero pulse without cam (§2.3.3.3): the logic is armed at the start (0); the pulse -2.5 at 10 mm/s after
    # 0.02 + 2.4/10 = 0.26 s. No cam, so no offset.
    pulse = reference_json("kenngr.ref_ohne_nocken 1\nkenngr.ref_ohne_rev 1\n", zero_pulse_phase=-2.5)
    assert approx(pulse["time"], 0.26) and approx(pulse["armed_at"], 0.0)
    assert pulse["cam_zero_pulse_offset"] is None


SPINDLE = (
    b"kenngr.antr_typ 1\nkenngr.achs_typ 4\nkenngr.achs_mode 0x4\nkenngr.ref_ohne_rev 1\nkenngr.ref_richt 1\n"
    b"getriebe[0].vb_reflow 36000\ngetriebe[0].lslope_profil.a_grenz_stufe_1 360\n"
    b"getriebe[0].lslope_profil.a_grenz_stufe_2 720\nEnde\n"
)


def test_flying_spindle_offset_counts_from_where_the_cam_is_left():
    # 36 °/s with 360 °/s² (t_acc 0.1 s, 1.8°). The cam [260, 280] counts where it is left (§2.3.2.1): at 280°,
    # t = 0.1 + 278.2/36 = 7.82778 s, seen at the 7.828 s cycle at 1.8 + 36 × 7.728 = 280.008°. The pulse at 300°
    # arrives at 0.1 + 298.2/36 = 8.38333 s. Offset 300 - 280.008 = 19.992°; armed at 280.008°.
    scenario = ScenarioInput(cam=(260.0, 280.0), zero_pulse_period=360.0, zero_pulse_phase=300.0)
    run = dry_run(SPINDLE, "s.lis", scenario)
    reference = trace_json(run)["reference"]
    assert approx(reference["time"], 0.1 + 298.2 / 36, 1e-9)
    assert approx(reference["armed_at"], 280.008, 1e-9)
    assert approx(reference["cam_zero_pulse_offset"], 19.992, 1e-9)
    console = Console(file=io.StringIO(), width=200, color_system=None)
    render(run, console)
    text = console.file.getvalue()
    assert "Zero-pulse logic armed at 280.008 °; reference cam - zero pulse offset 19.992 °" in text
    assert "becomes 0 °, at 8.383 s" in text


def test_a_fixed_stop_reference_time_is_when_the_stop_is_detected():
    # TORQ on SERCOS (the axis of test_engine.test_fixed_stop_by_hand): 5 mm/s at 50 mm/s², t_acc 0.1 s,
    # d_acc 0.25 mm; the stop at 20 mm is reached after 0.1 + 19.75/5 = 4.05 s and detected torq_detect_time
    # (25000 µs) later: the reference time is 4.075 s. No zero pulse: no arming point, no offset.
    text = (
        b"kenngr.antr_typ 2\nkenngr.homing.homing_type TORQ\nkenngr.homing.torq_homing_dir POSITIVE\n"
        b"antr.fixed_stop.drive_ident[0].id TORQUE_LIMIT\n"  # required for the move (P-AXIS-00719, LIS328)
        b"getriebe[0].homing.torq_move_velocity 5000\ngetriebe[0].homing.torq_move_acceleration 50\n"
        b"kenngr.homing.torq_max_distance 2000000\nkenngr.homing.torq_detect_time 25000\nEnde\n"
    )
    reference = trace_json(dry_run(text, "t.lis", ScenarioInput(start_position=0.0, fixed_stop=20.0)))[
        "reference"
    ]
    assert reference["kind"] == "fixed stop" and approx(reference["time"], 4.075)
    assert reference["armed_at"] is None and reference["cam_zero_pulse_offset"] is None

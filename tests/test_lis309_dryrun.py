"""LIS309 and the dry-run agree (issue 26 item 10): a rotary axis in linear mode has no modulo range for either
(P-AXIS-00015 LINEAR / MODULO), and a homing_max_movement_dist (P-AXIS-00412) that LIS309 accepts does not make the
dry-run sweep fail. Both read path monitoring as the distance from the homing start position (TF5200 §2.4.1).

Worst cases by hand, in the dry-run's default geometry: a modulo rotary axis (cam 30° wide, a pulse every 10°, the
first 5° after the cam edge) needs less than 360 - 30 + 30 = 360°. A spindle with a cam needs up to a revolution
to the cam edge and, its zero pulse coming once per revolution, up to another revolution after the arming point:
below 2 × 360° + shift_offset_zero_pulse_activation (P-AXIS-00494)."""

from __future__ import annotations

import pytest

from achslint import lint
from achslint.dryrun import prepare, sweep

ROTARY = (
    "kenngr.antr_typ 1\nkenngr.achs_typ 2\nkenngr.achs_mode 0x4\nkenngr.ref_richt 0\nlr_hw[0].cam_direct_access 0\n"
    "getriebe[0].vb_refmax 100000\ngetriebe[0].vb_reflow 10000\ngetriebe[0].a_ref 500\n"
)
SPINDLE = (
    "kenngr.antr_typ 1\nkenngr.achs_typ 4\nkenngr.achs_mode 0x4\nkenngr.ref_ohne_rev 1\n"
    "getriebe[0].vb_reflow 36000\ngetriebe[0].lslope_profil.a_grenz_stufe_1 360\n"
    "getriebe[0].lslope_profil.a_grenz_stufe_2 720\n"
)


def lis309(text: str) -> list[str]:
    return [d.message for d in lint((text + "Ende\n").encode(), name="achsmds1.lis") if d.code == "LIS309"]


def failed(text: str, runs: int = 600) -> int:
    summary = sweep(prepare((text + "Ende\n").encode(), "a.lis"), runs)
    assert summary["runs"] == runs
    return int(summary["outcomes"].get("failed", 0))


def test_a_rotary_axis_in_linear_mode_has_no_modulo_range():
    # achs_mode 0x1 (LINEAR: a rotary axis with a restricted range): 180° of path monitoring is not "shorter than
    # the modulo range" — there is none, for LIS309 as for the dry-run, which counts the axis without wrapping.
    text = ROTARY.replace("0x4", "0x1") + "kenngr.homing_max_movement_dist 1800000\n"
    assert lis309(text) == []
    assert prepare((text + "Ende\n").encode(), "a.lis").modulo is None
    assert lis309(ROTARY + "kenngr.homing_max_movement_dist 1800000\n")  # the same value counting modulo


@pytest.mark.parametrize("variant", ["", "kenngr.ref_ohne_rev 1\n", "kenngr.homing_without_zero_pulse 1\n"])
def test_exactly_one_modulo_range_on_a_rotary_axis_never_fails_the_sweep(variant):
    text = ROTARY + variant + "kenngr.homing_max_movement_dist 3600000\n"
    assert lis309(text) == []
    assert failed(text) == 0


def test_a_spindle_with_a_cam_needs_two_revolutions_and_the_sweep_agrees():
    one = SPINDLE + "kenngr.homing_max_movement_dist 3600000\n"
    [message] = lis309(one)
    assert "use at least 7200000" in message and "P-ERR-70394" in message
    # The default scene: cam [-120, -100] (= [240, 260]), left at 260, the pulse 180° after it. Starting just past
    # the cam the spindle turns ~360° to leave it and 180° more to the pulse: 360° is too short for about half of
    # the starts (those more than 180° before the cam's end), so some runs fail — as LIS309 says.
    assert failed(one) > 0
    two = SPINDLE + "kenngr.homing_max_movement_dist 7200000\n"
    assert lis309(two) == [] and failed(two) == 0
    # With a shift of 10° (100000 × 0.0001°) the minimum grows by the shift: 7300000.
    shifted = SPINDLE + "kenngr.shift_offset_zero_pulse_activation 100000\n"
    [message] = lis309(shifted + "kenngr.homing_max_movement_dist 7200000\n")
    assert "use at least 7300000" in message
    accepted = shifted + "kenngr.homing_max_movement_dist 7300000\n"
    assert lis309(accepted) == [] and failed(accepted) == 0


def test_a_spindle_without_cam_needs_one_revolution():
    # Flying homing without cam (ref_ohne_nocken 1): one zero pulse per revolution, armed at the start: < 360°.
    text = SPINDLE + "kenngr.ref_ohne_nocken 1\nkenngr.homing_max_movement_dist 3600000\n"
    assert lis309(text) == [] and failed(text) == 0
    # A spindle homing in three phases with a cam needs the two revolutions too.
    three = SPINDLE.replace("kenngr.ref_ohne_rev 1\n", "") + "kenngr.homing_max_movement_dist 7200000\n"
    assert lis309(three) == [] and failed(three) == 0
    assert lis309(three.replace("7200000", "3600000"))

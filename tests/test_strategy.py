"""Strategy classification and parameter effectiveness (TF5200 homing manual §2.3, §3.5)."""

from __future__ import annotations

import pytest

from achslint.axis.analysis import analyse
from achslint.axis.resolved import ResolvedAxis
from achslint.homing import NEGATIVE, POSITIVE, classify, effect
from achslint.syntax.parser import parse_text


def values_of(text: str) -> ResolvedAxis:
    return ResolvedAxis(analyse(parse_text(text + "\nEnde\n")))


def effectiveness(strategy, values, path):
    found = effect(strategy, values, path)
    return found.effective, found.reason


CASES = [
    # (list body, strategy id, manual type)
    ("kenngr.antr_typ 1", "cam_zero_pulse", "III"),
    ("kenngr.antr_typ 1\nkenngr.homing_without_zero_pulse 1", "cam_only", "I"),
    ("kenngr.antr_typ 1\nkenngr.ref_ohne_nocken 1\nkenngr.ref_ohne_rev 1", "zero_pulse_only", "II"),
    ("kenngr.antr_typ 1\nkenngr.ref_ohne_rev 1", "one_phase_cam_zero_pulse", "III"),
    ("kenngr.antr_typ 1\nkenngr.ref_ohne_rev 1\nkenngr.homing_without_zero_pulse 1", "one_phase_cam", "I"),
    ("kenngr.antr_typ 4", "simulation", None),
    ("kenngr.antr_typ 1\nkenngr.achs_typ 4\nkenngr.ref_ohne_rev 1", "spindle_flying_cam", None),
    (
        "kenngr.antr_typ 1\nkenngr.achs_typ 4\nkenngr.ref_ohne_rev 1\nkenngr.ref_ohne_nocken 1",
        "spindle_flying_zero_pulse",
        None,
    ),
    ("kenngr.antr_typ 2", "drive_controlled", None),  # SERCOS default homing type (P-AXIS-00299 table)
    ("kenngr.antr_typ 8", "cam_zero_pulse", "III"),  # CANopen default is CNC-controlled
    ("kenngr.antr_typ 2\nkenngr.homing_type CNC_CONTROLLED", "cam_zero_pulse", "III"),
    ("kenngr.antr_typ 2\nkenngr.homing.homing_type DRIVE_DEFAULT", "drive_controlled", None),
    ("kenngr.antr_typ 8\nkenngr.homing.homing_type TORQ", "fixed_stop", None),
    ("kenngr.abs_pos_gueltig 1", "absolute", "IV"),
    ("kenngr.abs_pos_gueltig 1\nkenngr.homing.homing_type DISABLED", "disabled", None),
    ("kenngr.abs_pos_gueltig 1\nkenngr.homing.homing_type IGNORE_ABS_POS", "ignore_abs_pos", None),
    ("kenngr.abs_pos_gueltig 0\nkenngr.homing.homing_type DISABLED", "disabled", None),
]


@pytest.mark.parametrize("body,strategy_id,manual_type", CASES)
def test_classification(body, strategy_id, manual_type):
    strategy = classify(values_of(body))
    assert (strategy.id, strategy.manual_type) == (strategy_id, manual_type)


def test_three_phase_sequence_directions_and_speeds():
    values = values_of(
        "kenngr.antr_typ 1\nkenngr.ref_richt 1\nkenngr.fast_from_cam 0\n"
        "getriebe[0].vb_refmax 100000\ngetriebe[0].vb_reflow 20000"
    )
    phases = classify(values).phases
    assert [(p.direction, p.velocity) for p in phases] == [
        (POSITIVE, 100000),  # phase 1 at vb_refmax in ref_richt
        (NEGATIVE, 20000),  # phase 2 off the cam, slow because fast_from_cam = 0
        (POSITIVE, 20000),  # phase 3 back at vb_reflow
    ]


def test_falling_edge_and_delayed_zero_pulse_variants():
    strategy = classify(
        values_of(
            "kenngr.antr_typ 1\nlr_hw[0].cam_level 0\nkenngr.ref_richt 0\nkenngr.shift_offset_zero_pulse_activation 5000"
        )
    )
    assert strategy.falling_edge
    assert any("falling edge" in v for v in strategy.variants)
    assert any("P-AXIS-00494" in v for v in strategy.variants)


def test_encoder_overflow_is_type_iii_with_the_overflow_as_event():
    strategy = classify(
        values_of("kenngr.antr_typ 5\nkenngr.homing_overflow_evaluation 1\nantr.encoder_bit_range 20")
    )
    assert strategy.id == "cam_zero_pulse"
    assert "encoder overflow" in strategy.phases[-1].ends_when


def test_reference_values_are_followed():
    values = values_of("getriebe[0].dynamik.vb_max 120000\ngetriebe[0].vb_refmax P-AXIS-00212.0")
    assert values.get("getriebe[0].vb_refmax") == 120000


# Effectiveness table of the manual (§3.5): X = effective, - = not effective.
TABLE = {
    #                          I     II     III    IV
    "kenngr.ref_ohne_rev": (True, True, True, False),
    "kenngr.ref_richt": (True, True, True, False),
    "kenngr.fast_from_cam": (True, False, True, False),
    "getriebe[0].pos_refpkt": (True, True, True, False),
    "getriebe[0].vb_reflow": (True, True, True, False),
    "getriebe[0].vb_refmax": (True, False, True, False),
    "lr_hw[0].cam_level": (True, False, True, False),
}
TYPES = {
    "I": "kenngr.antr_typ 1\nkenngr.homing_without_zero_pulse 1",
    "II": "kenngr.antr_typ 1\nkenngr.ref_ohne_nocken 1\nkenngr.ref_ohne_rev 1",
    "III": "kenngr.antr_typ 1",
    "IV": "kenngr.antr_typ 1\nkenngr.abs_pos_gueltig 1",
}


@pytest.mark.parametrize("path", sorted(TABLE))
def test_effectiveness_table_of_the_manual(path):
    for column, manual_type in enumerate(("I", "II", "III", "IV")):
        values = values_of(TYPES[manual_type])
        strategy = classify(values)
        assert strategy.manual_type == manual_type
        effective, reason = effectiveness(strategy, values, path)
        assert effective is TABLE[path][column], (path, manual_type, reason)
        assert reason


def test_drive_controlled_ignores_cnc_sequence_parameters():
    values = values_of("kenngr.antr_typ 2\nkenngr.homing.homing_type DRIVE_CONTROLLED")
    strategy = classify(values)
    assert effectiveness(strategy, values, "getriebe[0].vb_refmax")[0] is False
    assert effectiveness(strategy, values, "kenngr.abs_pos_gueltig")[0] is True


def test_simulation_only_uses_rpf_weg_bis_nip():
    values = values_of("kenngr.antr_typ 4\nantr.simu.rpf_weg_bis_nip 200")
    strategy = classify(values)
    assert effectiveness(strategy, values, "antr.simu.rpf_weg_bis_nip")[0] is True
    assert effectiveness(strategy, values, "getriebe[0].vb_refmax")[0] is False
    assert effectiveness(strategy, values, "lr_hw[0].cam_level")[0] is False
    assert effectiveness(strategy, values, "kenngr.fast_from_cam")[0] is False
    assert strategy.phases[0].ends_when.endswith("200 [0.1 µm] (= 0.02 mm)")

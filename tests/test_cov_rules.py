"""Rule branches the fixtures do not reach: each test is a small list and the findings (code and message)
the user gets for it, or the finding a close variant of the list must not get."""

from __future__ import annotations

from achslint import lint_text

SERCOS_SPINDLE = ("kenngr.achs_typ  4", "kenngr.antr_typ  2", "kenngr.achs_mode  0x104")


def found(*lines: str, select: list[str] | None = None) -> list[tuple[int, str, str]]:
    """(line, code, message) of the findings of a list of these lines and `Ende`."""
    text = "\n".join([*lines, "Ende", ""])
    return [(d.line, d.code, d.message) for d in lint_text(text, select=select)]


def test_lis001_explains_what_is_wrong_with_a_path_or_a_string() -> None:
    assert found(
        ";kenngr.ref_richt  1", "kenngr..ref_richt  1", "1kenngr.ref_richt  1", 'kopf.log_achs_name  "X"abc'
    ) == [
        (
            1,
            "LIS001",
            "syntax error in `;kenngr.ref_richt`: `;` does not start a comment in CNC lists; use `#` at the "
            "start of the line",
        ),
        (2, "LIS001", "syntax error in `kenngr..ref_richt`: empty member name between dots"),
        (3, "LIS001", "syntax error in `1kenngr.ref_richt`: a parameter path starts with a letter"),
        (
            4,
            "LIS001",
            'syntax error in the value of `kopf.log_achs_name`: text follows the closing `"` without a blank; '
            "put a space or `(` before the comment",
        ),
    ]


def test_lis202_names_the_data_type_when_the_manual_gives_no_range() -> None:
    assert found("lr_param.anz_driftwerte  -1") == [
        (
            1,
            "LIS202",
            "`lr_param.anz_driftwerte` = -1 is below the minimum 0 of UNS16; use a value of at least 0",
        )
    ]


def test_lis203_offers_capitals_for_a_symbol_in_small_letters() -> None:
    [(line, code, message)] = found("kenngr.homing.homing_type  cnc_controlled")
    assert (line, code) == (1, "LIS203")
    assert message.startswith(
        "`cnc_controlled` is not a value of `kenngr.homing.homing_type` (did you mean `CNC_CONTROLLED`?)"
    )
    [diagnostic] = lint_text("kenngr.homing.homing_type  cnc_controlled\nEnde\n")
    assert diagnostic.fix is not None and [e.content for e in diagnostic.fix.edits] == ["CNC_CONTROLLED"]


def test_lis103_old_and_new_name_with_the_same_value_only_repeat() -> None:
    codes = [
        code
        for _, code, _ in found(
            "kenngr.homing_type  CNC_CONTROLLED", "kenngr.homing.homing_type  CNC_CONTROLLED"
        )
    ]
    assert codes == ["LIS102", "LIS005"]  # no LIS103: both say the same


def test_lis310_reference_monitoring_half_configured_or_beyond_the_element() -> None:
    select = ["LIS310"]
    assert found(*SERCOS_SPINDLE, "antr.reference_check.bit_nr  3", select=select) == [
        (
            4,
            "LIS310",
            "`antr.reference_check.bit_nr` = 3 is set but no element name: name the telegram element "
            "(`S-0-0135` for the status word) in antr.reference_check.element_name",
        )
    ]
    assert found(*SERCOS_SPINDLE, "antr.reference_check.element_name  S-0-0135", select=select) == [
        (
            4,
            "LIS310",
            "`antr.reference_check.element_name` = S-0-0135 switches reference monitoring on, but "
            "antr.reference_check.bit_nr is not set; give the bit number of the 'drive is referenced' signal "
            "(P-ERR-110549)",
        )
    ]
    telegram = (
        *SERCOS_SPINDLE,
        "antr.sercos.at[1].ident_len  4",
        "antr.sercos.at[1].nc_ref  POSITION_FEEDBACK_VALUE_1",
        "antr.reference_check.bit_nr  40",
    )
    assert found(
        *telegram, "antr.reference_check.element_name  POSITION_FEEDBACK_VALUE_1", select=select
    ) == [
        (
            6,
            "LIS310",
            "`antr.reference_check.bit_nr` = 40 does not exist in the 4-byte element "
            "`POSITION_FEEDBACK_VALUE_1` (bits 0..31); the CNC switches monitoring off (P-ERR-110549)",
        )
    ]
    # an element the list does not describe: its size is unknown, so any bit is taken
    assert found(*telegram, "antr.reference_check.element_name  OTHER_ELEMENT", select=select) == []


def test_lis311_overflow_homing_switched_off_or_without_encoder_bits() -> None:
    select = ["LIS311"]
    [(_, _, switched_off)] = found(
        "kenngr.antr_typ  1",
        "kenngr.homing_overflow_evaluation  1",
        "antr.encoder_bit_range  10",
        select=select,
    )
    assert switched_off.startswith("`kenngr.homing_overflow_evaluation` = 1 (the CNC uses 0): ")
    assert switched_off.endswith("only SERCOS, Lightbus and CANopen drives support it (P-ERR-110416)")
    assert found("kenngr.antr_typ  5", "kenngr.homing_overflow_evaluation  1", select=select) == [
        (
            2,
            "LIS311",
            "`kenngr.homing_overflow_evaluation` = 1 but `antr.encoder_bit_range` = 0 (default): set the number "
            "of encoder bits (1..31) whose overflow marks the reference",
        )
    ]


def test_lis312_the_latch_is_switched_off_for_spindles() -> None:
    [(line, code, message)] = found(
        *SERCOS_SPINDLE, "antr.sercos.drive_supports_cnc_homing  1", select=["LIS312"]
    )
    assert (line, code) == (4, "LIS312")
    assert message.startswith("`antr.sercos.drive_supports_cnc_homing` = 1 (the CNC uses 0): ")
    assert "(P-ERR-110522)" in message


def test_lis320_a_spindle_with_keine_auto_rpf_is_not_homed_from_rotation() -> None:
    spindle = ("kenngr.achs_typ  4", "kenngr.antr_typ  1")
    assert [code for _, code, _ in found(*spindle, "kenngr.achs_mode  0x4", select=["LIS320"])] == ["LIS320"]
    assert found(*spindle, "kenngr.achs_mode  0x104", select=["LIS320"]) == []


def test_lis322_overflow_homing_needs_no_zero_pulse_latch() -> None:
    sercos = ("kenngr.antr_typ  2", "kenngr.homing.homing_type  CNC_CONTROLLED")
    assert [code for _, code, _ in found(*sercos, select=["LIS322"])] == ["LIS322"]
    overflow = ("kenngr.homing_overflow_evaluation  1", "antr.encoder_bit_range  20")
    assert found(*sercos, *overflow, select=["LIS322"]) == []


def test_lis315_a_further_gear_stage_without_its_own_move_values_is_fine() -> None:
    fixed_stop = (
        "kenngr.antr_typ  2",
        "kenngr.homing.homing_type  TORQ",
        "kenngr.homing.torq_detect_time  10",
        "getriebe[0].homing.torq_move_velocity  1000",
        "getriebe[0].homing.torq_move_acceleration  100",
    )
    assert found(*fixed_stop, "getriebe[2].nummer  1", select=["LIS315"]) == []
    # without the acceleration of gear stage 0 there is one finding, for gear stage 0 only
    assert [
        message for _, _, message in found(*fixed_stop[:4], "getriebe[2].nummer  1", select=["LIS315"])
    ] == [
        "gear stage 0: `getriebe[0].homing.torq_move_acceleration` = 0 mm/s² (default): fixed-stop homing needs "
        "a move acceleration of at least 1 (P-AXIS-00334); without it the axis does not move"
    ]

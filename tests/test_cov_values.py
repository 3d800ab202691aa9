"""How written values are read (analysis.py) for the less common spellings: TRUE/FALSE, quoted symbols,
comments where the value belongs, booleans with symbols, strictly positive reals, two-index paths,
repeated wrong values — each seen through the findings `achslint lint` reports."""

from __future__ import annotations

from achslint import lint_text
from achslint.resolved import resolve_bytes


def found(*lines: str) -> list[tuple[int, str, str]]:
    """(line, code, message) of the findings of a list of these lines and `Ende`."""
    return [(d.line, d.code, d.message) for d in lint_text("\n".join([*lines, "Ende", ""]))]


def test_true_false_and_quoted_symbols_are_accepted() -> None:
    assert found("kenngr.ref_richt  TRUE", "kenngr.ref_ohne_rev  FALSE") == []
    assert found('kenngr.homing.homing_type  "CNC_CONTROLLED"') == []
    axis = resolve_bytes(b"kenngr.ref_richt  TRUE\nkenngr.ref_ohne_rev  FALSE\nEnde\n", "axis.lis")
    assert axis.get("kenngr.ref_richt") is True and axis.get("kenngr.ref_ohne_rev") is False


def test_a_boolean_written_as_a_real_or_text_is_wrong() -> None:
    assert found("kenngr.ref_richt  1.0") == [
        (1, "LIS201", "`kenngr.ref_richt` is BOOLEAN: write 0 (off) or 1 (on), not `1.0`")
    ]
    assert found('kenngr.ref_richt  "1"') == [
        (1, "LIS201", '`kenngr.ref_richt` is BOOLEAN: write 0 (off) or 1 (on), not `"1"`')
    ]


def test_a_comment_where_the_value_belongs_means_no_value() -> None:
    assert found("kenngr.ref_richt  ( search direction") == [
        (1, "LIS201", "`kenngr.ref_richt` has no value; 0 or 1 is expected")
    ]


def test_a_boolean_with_symbols_takes_only_its_symbols() -> None:
    [(line, code, message)] = [f for f in found("kenngr.homing.torq_homing_dir  UP") if f[1] != "LIS401"]
    assert (line, code) == (1, "LIS203")
    assert message == "`UP` is not a value of `kenngr.homing.torq_homing_dir`; accepted: NEGATIVE, POSITIVE"
    axis = resolve_bytes(b"kenngr.homing.torq_homing_dir  POSITIVE\nEnde\n", "axis.lis")
    assert axis.get("kenngr.homing.torq_homing_dir") is True


def test_a_symbol_number_that_names_no_symbol() -> None:
    assert found("kenngr.achs_typ  7") == [
        (
            1,
            "LIS203",
            "`7` is not a value of `kenngr.achs_typ`; accepted: ACHSTYP_TRANSLATOR, ACHSTYP_ROTATOR, "
            "ACHSTYP_SPINDEL (or their numbers 1, 2, 4)",
        )
    ]


def test_the_axis_type_written_as_a_symbol_sets_the_units() -> None:
    # a rotary axis: accelerations are in °/s² in the messages
    [(_, code, message)] = found(
        "kenngr.achs_typ  ACHSTYP_ROTATOR", "kenngr.antr_typ  1", "lr_hw[0].cam_direct_access  0"
    )
    assert code == "LIS404" and "1000 °/s² (default)" in message


def test_strictly_positive_reals_and_text_for_a_real() -> None:
    assert found("handbetrieb.hr.aufl[0]  0", "handbetrieb.hr.aufl[1]  abc") == [
        (1, "LIS202", "`handbetrieb.hr.aufl[0]` = 0 [0.1 µm/rev] must be greater than 0"),
        (2, "LIS201", "`handbetrieb.hr.aufl[1]` expects a number (REAL64), not the text `abc`"),
    ]


def test_the_second_index_of_a_two_index_path_is_checked() -> None:
    assert found("getriebe[0].achs_position[2]  1") == []
    assert found("getriebe[0].achs_position[99]  1") == [
        (
            1,
            "LIS104",
            "index 99 of `achs_position` in `getriebe[0].achs_position[99]` is out of bounds: P-AXIS-00017 "
            "allows achs_position[0]..achs_position[2] (indices are zero-based)",
        )
    ]


def test_a_wrong_value_repeated_is_the_same_value_repeated() -> None:
    assert [f[:2] for f in found("kenngr.ref_richt 7", "kenngr.ref_richt 7")] == [
        (1, "LIS201"),
        (2, "LIS005"),
        (2, "LIS201"),
    ]
    repeated = found("kenngr.ref_richt 7", "kenngr.ref_richt 7")[1][2]
    assert (
        repeated
        == "`kenngr.ref_richt` is assigned again with the same value (first on line 1); delete the repetition"
    )


def test_a_missing_value_says_what_is_expected() -> None:
    assert found("kenngr.homing.homing_type") == [
        (
            1,
            "LIS201",
            "`kenngr.homing.homing_type` has no value; one of DRIVE_DEFAULT, NONE, TORQ, CNC_CONTROLLED, "
            "DRIVE_CONTROLLED, DISABLED, IGNORE_ABS_POS is expected",
        )
    ]
    assert found("kenngr.ref_richt  # search direction") == [
        (1, "LIS201", "`kenngr.ref_richt` has no value (`#` starts a comment); 0 or 1 is expected")
    ]
    assert found("kenngr.swe_pos  ( upper limit") == [
        (1, "LIS201", "`kenngr.swe_pos` has no value; a number (REAL64) is expected")
    ]


def test_an_unknown_axis_type_symbol_leaves_the_axis_linear() -> None:
    findings = found("kenngr.achs_typ  LINEAR", "kenngr.antr_typ  1", "lr_hw[0].cam_direct_access  0")
    assert [code for _, code, _ in findings] == ["LIS404", "LIS203"]
    assert "1000 mm/s² (default)" in findings[0][2]  # linear units, not °/s²

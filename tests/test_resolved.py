"""The resolved axis: the CNC's load-time corrections, and one truth for lint, explain, dry-run and the model;
then how written values are read for the less common spellings (TRUE/FALSE, quoted symbols, comments where
the value belongs, symbols of booleans, strictly positive reals, two-index paths, repeated wrong values),
seen through the findings of `lint` and the resolved value."""

from __future__ import annotations

import pytest
from pydantic import ValidationError

import achslint
from achslint import lint_text
from achslint.axis.corrections import encoder_revolution
from achslint.axis.resolved import resolve_bytes
from achslint.dryrun import dry_run
from achslint.explanation import explain_list
from achslint.model import axis_model, dumps

from .conftest import FIXTURES


def resolved(text: str):
    return resolve_bytes((text + "\nEnde\n").encode(), "t.lis")


def corrections(text: str) -> dict:
    return {c.parameter: (c.written, c.used, c.error) for c in resolved(text).corrections}


@pytest.mark.parametrize(
    "text,expected",
    [
        # P-AXIS-00299: drive-controlled homing on a simulated drive -> the drive's default (P-ERR-110384).
        (
            "kenngr.antr_typ 4\nkenngr.homing.homing_type DRIVE_CONTROLLED",
            {"kenngr.homing.homing_type": ("DRIVE_CONTROLLED", "CNC_CONTROLLED", "P-ERR-110384")},
        ),
        # P-AXIS-00268 caps both homing speeds and the fixed-stop speed (P-ERR-110421/110422/110413).
        (
            "kenngr.antr_typ 1\ngetriebe[1].vb_not_referenced 10000\ngetriebe[1].vb_refmax 50000\n"
            "getriebe[1].vb_reflow 20000\ngetriebe[1].homing.torq_move_velocity 30000",
            {
                "getriebe[1].vb_refmax": (50000, 10000, "P-ERR-110421"),
                "getriebe[1].vb_reflow": (20000, 10000, "P-ERR-110422"),
                "getriebe[1].homing.torq_move_velocity": (30000, 10000, "P-ERR-110413"),
            },
        ),
        # P-AXIS-00354: 2^10 increments of 0.1 µm = 1024; an offset of 5000 is beyond one revolution (P-ERR-70310).
        (
            "kenngr.antr_typ 5\nkenngr.homing_overflow_evaluation 1\nantr.encoder_bit_range 10\nantr.encoder_overflow_offset 5000",
            {"antr.encoder_overflow_offset": (5000, 0, "P-ERR-70310")},
        ),
        # P-AXIS-00294 on a terminal drive is switched off (P-ERR-110416); the offset is then not looked at.
        (
            "kenngr.antr_typ 6\nkenngr.homing_overflow_evaluation 1\nantr.encoder_bit_range 10\nantr.encoder_overflow_offset 5000",
            {"kenngr.homing_overflow_evaluation": (True, False, "P-ERR-110416")},
        ),
        # P-AXIS-00386 on a spindle (P-ERR-110522); P-AXIS-00388 on a CANopen drive (P-ERR-110516).
        (
            "kenngr.antr_typ 2\nkenngr.achs_typ 4\nkenngr.achs_mode 0x4\nantr.sercos.drive_supports_cnc_homing 1",
            {"antr.sercos.drive_supports_cnc_homing": (True, False, "P-ERR-110522")},
        ),
        ("kenngr.antr_typ 8\nantr.cnc_homing_encoder 2", {"antr.cnc_homing_encoder": (2, 0, "P-ERR-110516")}),
        # P-AXIS-00387 outside 1..16 while the latch is on (P-ERR-110514).
        (
            "kenngr.antr_typ 2\nantr.sercos.drive_supports_cnc_homing 1\nantr.sercos.cnc_homing_rt_bit_layout 0",
            {"antr.sercos.cnc_homing_rt_bit_layout": (0, 1, "P-ERR-110514")},
        ),
        # P-AXIS-00412 on a linear axis (P-ERR-110545); reference monitoring on CANopen (P-ERR-110548).
        (
            "kenngr.antr_typ 1\nkenngr.homing_max_movement_dist 3600000",
            {"kenngr.homing_max_movement_dist": (3600000, 0, "P-ERR-110545")},
        ),
        (
            "kenngr.antr_typ 8\nantr.reference_check.element_name S-0-0135\nantr.reference_check.bit_nr 6",
            {"antr.reference_check.element_name": ("S-0-0135", "", "P-ERR-110548")},
        ),
        # Nothing to correct.
        (
            "kenngr.antr_typ 2\nkenngr.homing.homing_type DRIVE_CONTROLLED\ngetriebe[0].vb_not_referenced 0",
            {},
        ),
    ],
)
def test_load_time_corrections(text, expected):
    assert corrections(text) == expected


def test_corrected_value_is_what_every_command_uses():
    text = b"kenngr.antr_typ 4\nkenngr.homing.homing_type DRIVE_CONTROLLED\nantr.simu.rpf_weg_bis_nip 300\nEnde\n"
    axis = resolve_bytes(text, "t.lis")
    assert axis.written("kenngr.homing.homing_type") == "DRIVE_CONTROLLED"
    assert axis.get("kenngr.homing.homing_type") == "CNC_CONTROLLED"
    report = explain_list(text, "t.lis")
    assert report["strategy"]["id"] == "simulation"
    assert report["corrections"][0]["error"] == "P-ERR-110384"
    row = {r["parameter"]: r for r in report["parameters"]}["antr.simu.rpf_weg_bis_nip"]
    assert row["effective"] is True  # the one parameter that matters for the corrected strategy
    assert dry_run(text, "t.lis").trace.strategy.id == "simulation"
    codes = {d.code for d in achslint.lint(text)}
    assert "LIS305" in codes and "LIS401" not in codes
    assert achslint.load(text).kenngr.homing.homing_type == "CNC_CONTROLLED"


def test_capped_speeds_are_explained_and_simulated_at_the_cap():
    text = (
        b"kenngr.antr_typ 1\ngetriebe[0].vb_not_referenced 10000\ngetriebe[0].vb_refmax 50000\n"
        b"getriebe[0].vb_reflow 5000\ngetriebe[0].a_ref 500\nEnde\n"
    )
    report = explain_list(text, "t.lis")
    assert report["phases"][0]["velocity"] == 10000  # phase 1 at the cap, not at vb_refmax 50000
    assert dry_run(text, "t.lis").trace.phases[0].velocity == pytest.approx(10.0)  # mm/s


def test_references_resolve_the_same_in_load_and_lint():
    text = b"getriebe[0].dynamik.vb_max 120000\ngetriebe[0].vb_refmax P-AXIS-00212.0\nkenngr.swe_pos.zero_limit 5\nEnde\n"
    model = achslint.load(text)
    assert model.getriebe[0].vb_refmax == resolve_bytes(text, "t").get("getriebe[0].vb_refmax") == 120000
    assert model.get("kenngr.swe_pos.zero_limit") == 5


def test_model_validate_enforces_the_cross_rules_with_every_violation():
    # No cam but with reversal (LIS301), and the reference position beyond the positive software limit (LIS313).
    data = {
        "kenngr": {"antr_typ": 1, "ref_ohne_nocken": True, "ref_ohne_rev": False, "swe_pos": 1000000},
        "getriebe": [{"pos_refpkt": 2000000}] + [{}] * 5,
    }
    with pytest.raises(ValidationError) as caught:
        axis_model().model_validate(data)
    found = {(error["ctx"]["code"], error["loc"]) for error in caught.value.errors()}
    assert ("LIS301", ("kenngr", "ref_ohne_nocken")) in found
    assert ("LIS313", ("getriebe", 0, "pos_refpkt")) in found
    fine = axis_model().model_validate({"kenngr": {"antr_typ": 1}})
    assert fine.kenngr.antr_typ == 1


def test_load_is_lenient_and_strict_raises():
    text = b"kenngr.antr_typ 1\nkenngr.ref_ohne_nocken 1\nkenngr.ref_ohne_rev 0\nEnde\n"
    model = achslint.load(text)
    assert [d.code for d in model.findings if d.severity.value == "error"] == ["LIS301"]
    with pytest.raises(ValidationError) as caught:
        achslint.load(text, strict=True)
    assert caught.value.errors()[0]["ctx"]["code"] == "LIS301"


def test_dumps_round_trips_through_load():
    model = achslint.load(FIXTURES / "lists" / "achsmds1.lis")
    again = achslint.load(dumps(model).encode())
    assert again.model_dump() == model.model_dump()


@pytest.mark.parametrize(
    "name,strategy,errors",
    [
        ("conventional_x.lis", "cam_zero_pulse", []),
        ("simulation_x.lis", "simulation", []),
        ("sercos_s0146.lis", "cam_zero_pulse", []),
        # The manual's TORQ excerpt leaves out torq_move_velocity (P-AXIS-00333 needs at least 1).
        ("torq_sercos.lis", "fixed_stop", ["LIS315"]),
    ],
)
def test_manual_examples_name_the_strategy_the_cnc_runs(name, strategy, errors):
    path = FIXTURES / "manual" / name
    report = explain_list(path.read_bytes(), name)
    assert report["strategy"]["id"] == strategy
    assert sorted({d.code for d in achslint.lint(path) if d.severity.value == "error"}) == errors
    if strategy == "fixed_stop":
        # No braking note: the axis ends after the retraction; the speeds capped by vb_not_referenced are listed.
        assert report["strategy"]["ends_with_braking"] is False
        assert {c["error"] for c in report["corrections"]} == {"P-ERR-110421", "P-ERR-110422"}
        assert report["phases"][0]["text"].startswith("1. to the fixed stop: no move")


@pytest.mark.parametrize(("name", "effective"), [("tr_ref_linear", False), ("tr_ref_trapezoid", True)])
def test_ramp_time_of_homing_counts_only_with_a_non_linear_slope(name, effective):
    """P-AXIS-00286 (tr_ref) shapes the homing moves only when getriebe[i].slope_type (P-AXIS-00270) is not
    the step-shaped profile 0 (homing manual §3.2.4): LIS401 names it on the linear slope, and explain agrees."""
    data = (FIXTURES / "homing" / f"{name}.lis").read_bytes()
    codes = {d.code for d in achslint.lint(data) if d.parameter == "getriebe[0].tr_ref"}
    assert codes == (set() if effective else {"LIS401"})
    rows = {row["parameter"]: row for row in explain_list(data, f"{name}.lis")["parameters"]}
    assert rows["getriebe[0].tr_ref"]["effective"] is effective


def test_an_encoder_bit_range_referenced_beyond_its_range_gives_no_revolution():
    # kenngr.achs_mode (P-AXIS-00015) holds 0x40000001 = 1073741825; as encoder_bit_range (0..31) by reference,
    # 2^1073741825 increments is no encoder: no overflow lattice and no correction (it ended in an
    # OverflowError before).
    axis = resolved(
        "kenngr.antr_typ 5\nkenngr.homing.homing_type CNC_CONTROLLED\nkenngr.homing_overflow_evaluation 1\n"
        "kenngr.achs_mode 0x40000001\nantr.encoder_bit_range P-AXIS-00015\nantr.encoder_overflow_offset 5"
    )
    assert axis.get("antr.encoder_bit_range") == 0x40000001
    assert encoder_revolution(axis, 0) is None
    assert axis.correction("antr.encoder_overflow_offset") is None


# --- written values: the less common spellings ---------------------------------------------------------


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

"""Every rule against its fixtures: `bad.*` must produce exactly the findings of
its snapshot `bad.snap`, `good.*` none of them. Then the branches a fixture pair does not show: a small
list each, and the findings (code and message) the user gets for it, or must not get for a close variant."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

from achslint import lint_text
from achslint.api import lint
from achslint.rules import registry

from .conftest import FIXTURES

RULE_DIRS = sorted(p for p in (FIXTURES / "rules").iterdir() if p.is_dir())


def _snapshots():
    tools = Path(__file__).resolve().parents[1] / "tools"
    if str(tools) not in sys.path:
        sys.path.insert(0, str(tools))
    import update_snapshots

    return update_snapshots


fixture = _snapshots().fixture
selection = _snapshots().selection


def machine_findings(folder, select):
    """Lint a machine folder (through its start-up list when it has one), as the CLI does."""
    return sorted((Path(d.path).name, d.line, d.code) for d in _snapshots().lint_fixture(folder, select))


@pytest.mark.parametrize("rule_dir", RULE_DIRS, ids=[p.name for p in RULE_DIRS])
def test_bad_fixture_matches_its_snapshot(rule_dir):
    """Every finding of the rule on `bad.*` — position, end, severity, message, related locations and the
    fix as a diff — is exactly what `bad.snap` holds (`python tools/update_snapshots.py CODE` rewrites it)."""
    snapshots = _snapshots()
    # The snapshot is its header line, then what the rule reports (nothing after the header: no finding);
    # read from it rather than linted once more for the check that there is something.
    rendered = snapshots.render(rule_dir)
    found = rendered.partition("\n")[2]
    if snapshots.is_dry_run_rule(rule_dir):
        assert found, f"{rule_dir.name}: the dry-run of the bad fixture must report it"
    else:
        assert found, f"{rule_dir.name}: the bad fixture must trigger the rule"
    snap = rule_dir / "bad.snap"
    assert snap.exists(), f"no {snap}: run python tools/update_snapshots.py {rule_dir.name}"
    assert rendered == snap.read_text(encoding="utf-8"), (
        f"{rule_dir.name} changed: run python tools/update_snapshots.py {rule_dir.name} and review the diff"
    )


@pytest.mark.parametrize("rule_dir", RULE_DIRS, ids=[p.name for p in RULE_DIRS])
def test_good_fixture_is_clean_for_rule(rule_dir):
    code = rule_dir.name
    if _snapshots().is_dry_run_rule(rule_dir):
        assert _snapshots().dry_run_warnings(rule_dir, "good") == []
        return
    good = fixture(rule_dir, "good")
    if good.is_dir() or good.suffix == ".nc":
        assert [row for row in machine_findings(good, selection(rule_dir)) if row[2] == code] == []
        return
    assert [d for d in lint(good, select=selection(rule_dir)) if d.code == code] == []


@pytest.mark.parametrize("rule_dir", RULE_DIRS, ids=[p.name for p in RULE_DIRS])
def test_good_fixture_has_no_errors_at_all(rule_dir):
    """The good variant is a correct list: no rule reports an error or warning on it."""
    good = fixture(rule_dir, "good")
    if good.is_dir() or good.suffix == ".nc":
        assert [row for row in machine_findings(good, None)] == []
        return
    found = [d for d in lint(good) if d.severity.value != "info"]
    assert found == []


def test_every_rule_has_fixtures():
    missing = [code for code in registry() if not list((FIXTURES / "rules" / code).glob("bad.*"))]
    assert missing == []


def test_lis203_similarity_is_what_difflib_would_choose():
    # The rule scores each written word once (message and fix share it); the choice must stay the one
    # difflib.get_close_matches makes for the message (cutoff 0.6) and for the fix (two at 0.8).
    import difflib
    import random

    from achslint.rules.lis203_unknown_symbol import _similar

    accepted = ("TORQ", "IGNORE_ABS_POS", "DISABLED", "CONTINUOUS", "ZERO_PULSE", "NO_ZERO_PULSE", "TORQUE")
    rnd = random.Random(7)
    for _ in range(2000):
        text = "".join(rnd.choice("TORQUEZEROPULSAB_ICDN") for _ in range(rnd.randint(1, 14)))
        chosen = tuple(rnd.sample(accepted, rnd.randint(1, len(accepted))))
        for n, cutoff in ((1, 0.6), (2, 0.8)):
            expected = difflib.get_close_matches(text, chosen, n=n, cutoff=cutoff)
            assert [s for score, s in _similar(text, chosen) if score >= cutoff][:n] == expected


@pytest.mark.parametrize(
    ("name", "number", "expected"),
    [
        ("default_mds.lis", "0", []),  # what the CNC requires of a default list (P-ERR-110300)
        ("default_mds.lis", "-1", [("LIS506", "error")]),  # one finding: LIS202 leaves it to LIS506
        ("default_mds.lis", "7", [("LIS506", "error")]),
        ("achsmds1.lis", "0", [("LIS202", "error")]),  # an axis needs a logical number of at least 1
        ("achsmds1.lis", "7", []),
    ],
)
def test_the_logical_axis_number_of_a_default_list_and_of_an_axis(name, number, expected):
    found = lint(f"kopf.achs_nr  {number}\nEnde\n".encode(), name=name)
    assert [(d.code, d.severity.value) for d in found if d.code in ("LIS202", "LIS506")] == expected


# --- rule branches the fixtures do not reach -------------------------------------------------------

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

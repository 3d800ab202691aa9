"""Load-time checks of issue 26 item 8: the CNC's corrections of a_ref (P-ERR-110393), tr_ref (P-ERR-110394) and
a spindle's axis mode (P-ERR-110352) as the rules, explain and the dry-run see them; fixed-stop homing without a
torque limit (LIS328); gantry pairs with different or drive-controlled homing types (LIS510, LIS511); and
cam_direct_access judged the same whether written or left at its default (LIS321).

Every number is worked out by hand in the comments; ramps are trapezoidal (t = v/a, d = v²/2a)."""

from __future__ import annotations

from pathlib import Path

import pytest

from achslint import lint
from achslint.api import LintRequest, run_lint
from achslint.axis.resolved import resolve_bytes
from achslint.core.diagnostics import Severity
from achslint.dryrun import DryRunRefused, dry_run
from achslint.explanation import explain_list
from achslint.homing.scenario_input import ScenarioInput
from achslint.linting.config import Overrides

from .conftest import one_machine


def listed(text: str) -> bytes:
    return (text + "Ende\n").encode("latin-1")


def found(text: str, code: str) -> list[str]:
    return [d.message for d in lint(listed(text), name="achsmds1.lis") if d.code == code]


def corrections(text: str) -> dict:
    return {
        c.parameter: (c.written, c.used, c.error) for c in resolve_bytes(listed(text), "t.lis").corrections
    }


# A conventional linear axis with a cam, cam signal from the PLC; homes negative, leaves the cam fast.
CAM_AXIS = (
    "kenngr.antr_typ 1\nkenngr.ref_richt 0\nkenngr.fast_from_cam 1\nlr_hw[0].cam_direct_access 0\n"
    "getriebe[0].vb_refmax 100000\ngetriebe[0].vb_reflow 10000\n"
)

# --- a_ref above a_max: P-AXIS-00285 / P-AXIS-00008, P-ERR-110393 ----------------------------------------


@pytest.mark.parametrize(
    "text,expected",
    [
        # Stage 0: 1200 > 800 -> 800. Stage 1: 900 < the default a_max 1000 -> kept.
        (
            "getriebe[0].dynamik.a_max 800\ngetriebe[0].a_ref 1200\ngetriebe[1].a_ref 900\n",
            {"getriebe[0].a_ref": (1200, 800, "P-ERR-110393")},
        ),
        # One above the stage's own a_max is corrected, equal is not.
        (
            "getriebe[2].dynamik.a_max 400\ngetriebe[2].a_ref 401\n",
            {"getriebe[2].a_ref": (401, 400, "P-ERR-110393")},
        ),
        ("getriebe[0].dynamik.a_max 400\ngetriebe[0].a_ref 400\n", {}),
        # 0 asks for the fallback min(a_grenz_stufe_1/2) (§3.2.4): nothing to correct even with a tiny a_max.
        ("getriebe[0].dynamik.a_max 1\ngetriebe[0].a_ref 0\n", {}),
    ],
)
def test_homing_acceleration_above_a_max_is_lowered_to_it(text, expected):
    assert corrections(text) == expected


def test_dry_run_and_explain_home_with_the_corrected_acceleration():
    text = CAM_AXIS + "getriebe[0].dynamik.a_max 500\ngetriebe[0].a_ref 2000\n"
    scene = ScenarioInput(
        start_position=0.0,
        cam=(-120.0, -100.0),
        zero_pulse_period=5.0,
        zero_pulse_phase=-102.5,
        hardware_latch=True,
        cycle_time_ms=1.0,
        limit_switches=(-1010.0, 1010.0),
    )
    trace = dry_run(listed(text), "axis.lis", scene).trace
    # a = 500 mm/s², not 2000: to 100 mm/s in 0.2 s over 10 mm, the remaining 90 mm to the cam edge at -100 in
    # 0.9 s -> 1.1 s (with 2000 it would be 0.05 + 97.5/100 = 1.025 s). Braking from 100 mm/s takes 10 mm more
    # (-110 at 1.3 s; 2.5 mm with 2000). The pulse at -102.5 is the reference; braking from vb_reflow 10 mm/s
    # takes 10²/1000 = 0.1 mm, so the axis stops at -102.6.
    assert trace.acceleration == 500
    assert trace.events[0].time == pytest.approx(1.1)
    assert trace.phases[0].end_position == pytest.approx(-110.0)
    assert trace.phases[0].end_time == pytest.approx(1.3)
    assert trace.reference is not None and trace.reference["position"] == pytest.approx(-102.5)
    assert trace.phases[-1].end_position == pytest.approx(-102.6)
    assert [w["code"] for w in trace.warnings] == ["P-ERR-110393"]
    report = explain_list(listed(text), "axis.lis")
    assert report["strategy"]["acceleration"] == {"value": 500.0, "source": "a_ref"}
    row = next(r for r in report["parameters"] if r["parameter"] == "getriebe[0].a_ref")
    assert (row["value"], row["written"], row["correction"]) == (500, 2000, "P-ERR-110393")
    # The rule says what explain and the dry-run do.
    (message,) = found(text, "LIS325")
    assert "`getriebe[0].a_ref` = 2000 mm/s² (the CNC uses 500 mm/s²)" in message
    assert "`getriebe[0].dynamik.a_max` = 500 mm/s²" in message and message.endswith("(P-ERR-110393)")


def test_a_ref_within_a_max_is_not_reported():
    assert found(CAM_AXIS + "getriebe[0].dynamik.a_max 500\ngetriebe[0].a_ref 500\n", "LIS325") == []


def test_a_ref_without_effect_is_left_to_lis401():
    # An absolute axis does not home: a_ref has no effect, LIS401 says so and LIS325 stays silent (the CNC's
    # correction still shows in explain and the dry-run's warnings).
    text = (
        "kenngr.antr_typ 1\nkenngr.abs_pos_gueltig 1\ngetriebe[0].dynamik.a_max 500\ngetriebe[0].a_ref 2000\n"
    )
    assert found(text, "LIS325") == []
    assert any("getriebe[0].a_ref" in m for m in found(text, "LIS401"))
    assert "getriebe[0].a_ref" in corrections(text)


# --- tr_ref below tr_min: P-AXIS-00286 / P-AXIS-00201, P-ERR-110394 --------------------------------------


@pytest.mark.parametrize(
    "text,expected",
    [
        # 5000 µs < 20000 µs -> 20000; stage 1 has the default tr_min 10000 µs: 1 µs -> 10000.
        (
            "getriebe[0].dynamik.tr_min 20000\ngetriebe[0].tr_ref 5000\ngetriebe[1].tr_ref 1\n",
            {
                "getriebe[0].tr_ref": (5000, 20000, "P-ERR-110394"),
                "getriebe[1].tr_ref": (1, 10000, "P-ERR-110394"),
            },
        ),
        # 0 takes tr_min without a message (§3.2.4); equal to tr_min is allowed.
        ("getriebe[0].dynamik.tr_min 20000\ngetriebe[0].tr_ref 0\n", {}),
        ("getriebe[0].dynamik.tr_min 20000\ngetriebe[0].tr_ref 20000\n", {}),
    ],
)
def test_homing_ramp_time_below_tr_min_is_raised_to_it(text, expected):
    assert corrections(text) == expected


def test_short_ramp_time_is_reported_where_it_takes_effect():
    short = "getriebe[0].dynamik.tr_min 20000\ngetriebe[0].tr_ref 5000\n"
    # With a non-linear slope the ramp time counts: LIS326 names both values and the CNC message.
    (message,) = found(CAM_AXIS + "getriebe[0].slope_type 2\n" + short, "LIS326")
    assert "`getriebe[0].tr_ref` = 5000 µs (= 5 ms) (the CNC uses 20000 µs (= 20 ms))" in message
    assert message.endswith("(P-ERR-110394)")
    report = explain_list(listed(CAM_AXIS + "getriebe[0].slope_type 2\n" + short), "a.lis")
    row = next(r for r in report["parameters"] if r["parameter"] == "getriebe[0].tr_ref")
    assert (row["value"], row["written"], row["correction"], row["effective"]) == (
        20000,
        5000,
        "P-ERR-110394",
        True,
    )
    # With the linear slope (slope_type 0) it has no effect: LIS401 says so, LIS326 does not contradict it.
    linear = CAM_AXIS + "getriebe[0].slope_type 0\n" + short
    assert found(linear, "LIS326") == []
    assert any("getriebe[0].tr_ref" in m for m in found(linear, "LIS401"))


def test_dry_run_reports_the_ramp_time_correction():
    text = CAM_AXIS + "getriebe[0].slope_type 2\ngetriebe[0].dynamik.tr_min 20000\ngetriebe[0].tr_ref 5000\n"
    warnings = dry_run(listed(text), "a.lis").trace.warnings
    assert [w["code"] for w in warnings if w["code"]] == ["P-ERR-110394"]
    assert "getriebe[0].tr_ref 5000 -> 20000" in warnings[0]["message"]


# --- a spindle's axis mode: P-AXIS-00015, P-ERR-110352 ------------------------------------------------------


@pytest.mark.parametrize(
    "text,expected",
    [
        # Not written: the default 0x1 (LINEAR) -> 0x4.
        ("kenngr.achs_typ 4\n", {"kenngr.achs_mode": (0x1, 0x4, "P-ERR-110352")}),
        # LINEAR | KEINE_AUTO_RPF -> MODULO | KEINE_AUTO_RPF: 0x101 -> 0x104.
        ("kenngr.achs_typ 4\nkenngr.achs_mode 0x101\n", {"kenngr.achs_mode": (0x101, 0x104, "P-ERR-110352")}),
        ("kenngr.achs_typ 4\nkenngr.achs_mode 0x104\n", {}),
        # Only spindles: a rotary axis may count linear (a restricted range).
        ("kenngr.achs_typ 2\nkenngr.achs_mode 0x1\n", {}),
    ],
)
def test_spindle_axis_mode_is_corrected_to_modulo(text, expected):
    assert corrections(text) == expected


def test_spindle_mode_finding_agrees_with_the_other_spindle_rule_and_explain():
    # A drive-controlled SERCOS spindle written LINEAR without KEINE_AUTO_RPF: the CNC runs 0x4, and LIS314 asks
    # for KEINE_AUTO_RPF on top of the mode in force: 0x4 | 0x100 = 0x104. Both findings name the same mode.
    text = "kenngr.achs_typ 4\nkenngr.antr_typ 2\nkenngr.achs_mode 0x1\nkenngr.homing.homing_type DRIVE_CONTROLLED\n"
    (modulo,) = found(text, "LIS327")
    assert modulo.startswith("the spindle's `kenngr.achs_mode` 0x1 has no MODULO bit (0x4); write 0x4:")
    assert modulo.endswith("(P-ERR-110352)")
    (keine,) = found(text, "LIS314")
    assert "(0x4)" in keine and keine.endswith("Use 0x104")
    report = explain_list(listed(text), "s.lis")
    assert [(c["parameter"], c["written"], c["used"]) for c in report["corrections"]] == [
        ("kenngr.achs_mode", 1, 4)
    ]


def test_spindle_mode_left_at_its_default_is_reported_and_simulated():
    text = "kenngr.achs_typ 4\nkenngr.antr_typ 1\nkenngr.ref_ohne_rev 1\n"
    (message,) = found(text, "LIS327")
    assert "`kenngr.achs_mode` 0x1 (default)" in message
    assert "P-ERR-110352" in [w["code"] for w in dry_run(listed(text), "s.lis").trace.warnings]
    assert found(text + "kenngr.achs_mode 0x4\n", "LIS327") == []


# --- fixed-stop homing without a torque limit: §2.3.3.4.1/.3, P-AXIS-00719 ---------------------------------------

TORQ = (
    "kenngr.homing.homing_type TORQ\nkenngr.homing.torq_max_distance 200000\nkenngr.homing.torq_detect_time 25000\n"
    "getriebe[0].homing.torq_move_velocity 2000\ngetriebe[0].homing.torq_move_acceleration 50\n"
)
LIMIT = (
    "antr.fixed_stop.drive_ident[{i}].id TORQUE_LIMIT\nantr.fixed_stop.drive_ident[{i}].wr_ident S_0_0092\n"
)


def severities(text: str, code: str) -> list[Severity]:
    return [d.severity for d in lint(listed(text), name="achsmds1.lis") if d.code == code]


@pytest.mark.parametrize("drive", ["2", "8"])  # SERCOS, CANopen: the CNC writes drive_ident to the drive
def test_fixed_stop_without_torque_limit_is_an_error_the_dry_run_refuses(drive):
    # P-AXIS-00719: TORQUE_LIMIT is required for the move; without it the CNC stops homing with P-ERR-70541.
    text = f"kenngr.antr_typ {drive}\n" + TORQ
    (message,) = found(text, "LIS328")
    assert "no antr.fixed_stop.drive_ident[i].id is TORQUE_LIMIT" in message and "P-ERR-70541" in message
    assert "full torque" not in message
    assert severities(text, "LIS328") == [Severity.ERROR]
    with pytest.raises(DryRunRefused, match="LIS328"):
        dry_run(listed(text), "achsmds1.lis")
    assert found(f"kenngr.antr_typ {drive}\n" + TORQ + LIMIT.format(i=3), "LIS328") == []


def test_a_torque_limit_that_is_never_sent_does_not_count():
    ignored = LIMIT.format(i=1) + "antr.fixed_stop.drive_ident[1].commu IGNORE\n"
    text = "kenngr.antr_typ 2\n" + TORQ + ignored
    (message,) = found(text, "LIS328")
    assert "`antr.fixed_stop.drive_ident[1].commu` IGNORE" in message and "full torque" in message
    # configured but not sent: no documented CNC error, so a warning, and the homing runs
    assert severities(text, "LIS328") == [Severity.WARNING]
    assert dry_run(listed(text), "achsmds1.lis").trace.strategy.id == "fixed_stop"
    # Another entry (the position-lag window) is no torque limit either.
    window = (
        "antr.fixed_stop.drive_ident[0].id MON_WINDOW\nantr.fixed_stop.drive_ident[0].wr_ident S_0_0159\n"
    )
    assert len(found("kenngr.antr_typ 2\n" + TORQ + window, "LIS328")) == 1


def test_torque_limit_is_only_asked_for_where_the_drive_pushes():
    # A simulated drive has no torque to limit; an absolute axis does not home at all.
    assert found("kenngr.antr_typ 4\nkenngr.homing.torq_distance_to_block 1000\n" + TORQ, "LIS328") == []
    assert found("kenngr.antr_typ 2\nkenngr.abs_pos_gueltig 1\n" + TORQ, "LIS328") == []
    assert found("kenngr.antr_typ 2\n", "LIS328") == []


# --- cam_direct_access written or by default: P-AXIS-00036, §3.1.2.3, §3.5 ----------------------------------------


def test_cam_direct_access_is_judged_the_same_written_or_by_default():
    cam = "kenngr.antr_typ 1\nkenngr.ref_ohne_nocken 0\n"
    written, default = found(cam + "lr_hw[0].cam_direct_access 1\n", "LIS321"), found(cam, "LIS321")
    assert len(written) == len(default) == 1
    assert written[0].startswith("`lr_hw[0].cam_direct_access` = 1:") and written[0].endswith("set it to 0")
    assert default[0].startswith("`lr_hw[0].cam_direct_access` = 1 (default):")
    assert default[0].endswith("write `lr_hw[0].cam_direct_access 0`")
    # explain calls the default 1 the effective value, which is what the finding judges.
    row = next(
        r
        for r in explain_list(listed(cam), "a.lis")["parameters"]
        if r["parameter"] == "lr_hw[0].cam_direct_access"
    )
    assert (row["value"], row["source"]["kind"], row["effective"]) == (1, "default", True)
    assert found(cam + "lr_hw[0].cam_direct_access 0\n", "LIS321") == []


def test_cam_direct_access_second_input_and_other_drives():
    cam = "kenngr.antr_typ 1\nlr_hw[0].cam_direct_access 0\n"
    # lr_hw[1] is judged where the list uses it, not by its default.
    assert found(cam, "LIS321") == []
    assert len(found(cam + "lr_hw[1].cam_direct_access 1\n", "LIS321")) == 1
    # SERCOS and CANopen deliver the cam as antr.reference_cam_signal says (P-AXIS-00036 names other drives).
    assert found("kenngr.antr_typ 2\nkenngr.homing.homing_type CNC_CONTROLLED\n", "LIS321") == []
    # Without a cam there is nothing to read.
    assert found("kenngr.antr_typ 1\nkenngr.ref_ohne_nocken 1\nkenngr.ref_ohne_rev 1\n", "LIS321") == []


# --- gantry pairs: P-AXIS-00070, P-ERR-70263, P-ERR-50429 --------------------------------------------------------


def machine(folder: Path, lists: dict[str, str], codes: list[str]) -> list[tuple[str, int, str, str]]:
    one_machine(folder)
    for name, text in lists.items():
        (folder / name).write_bytes(listed(text))
    outcome = run_lint(LintRequest([str(folder)], Overrides(select=codes), jobs=1))
    assert not outcome.errors, outcome.errors
    return sorted(
        (Path(d.path).name, d.line, d.code, d.message) for r in outcome.results for d in r.diagnostics
    )


MASTER = "kopf.achs_nr 1\nkopf.log_achs_name X1\n"
SLAVE = "kopf.achs_nr 2\nkopf.log_achs_name X2\nkenngr.achs_mode 0x20001\nkenngr.gantry_ax_nr 1\n"


def test_gantry_slave_with_another_homing_type(tmp_path):
    # The conventional master homes CNC_CONTROLLED by default; the slave writes NONE on line 5.
    rows = machine(
        tmp_path,
        {
            "achsmds1.lis": MASTER + "kenngr.antr_typ 1\n",
            "achsmds2.lis": SLAVE + "kenngr.antr_typ 1\nkenngr.homing.homing_type NONE\n",
        },
        ["LIS510", "LIS511"],
    )
    assert [row[:3] for row in rows] == [("achsmds2.lis", 6, "LIS510")]
    message = rows[0][3]
    assert (
        "homes with NONE" in message
        and "with CNC_CONTROLLED (kenngr.homing.homing_type not written" in message
    )
    assert "P-ERR-70263" in message and message.endswith("Use CNC_CONTROLLED in both lists")


def test_gantry_pair_with_the_same_homing_type_written_or_by_default(tmp_path):
    # Conventional drives default to CNC_CONTROLLED: the master writes it, the slave leaves it out.
    rows = machine(
        tmp_path,
        {
            "achsmds1.lis": MASTER + "kenngr.antr_typ 1\nkenngr.homing.homing_type CNC_CONTROLLED\n",
            "achsmds2.lis": SLAVE + "kenngr.antr_typ 1\n",
        },
        ["LIS510", "LIS511"],
    )
    assert rows == []


def test_drive_controlled_gantry_master_is_refused_once_with_its_slaves(tmp_path):
    # Two SERCOS slaves of a SERCOS master, none writes a homing type: all DRIVE_CONTROLLED by default.
    slave3 = SLAVE.replace("kopf.achs_nr 2", "kopf.achs_nr 3").replace("X2", "X3")
    outcome_rows = machine(
        tmp_path,
        {
            "achsmds1.lis": MASTER + "kenngr.antr_typ 2\n",
            "achsmds2.lis": SLAVE + "kenngr.antr_typ 2\n",
            "achsmds3.lis": slave3 + "kenngr.antr_typ 2\n",
        },
        ["LIS510", "LIS511"],
    )
    assert [row[:3] for row in outcome_rows] == [("achsmds1.lis", 1, "LIS511")]
    assert "slaves: " in outcome_rows[0][3] and "P-ERR-50429" in outcome_rows[0][3]
    assert "achsmds2.lis" in outcome_rows[0][3] and "achsmds3.lis" in outcome_rows[0][3]


def test_gantry_advice_never_recommends_what_the_other_gantry_rule_refuses(tmp_path):
    # Master SERCOS (DRIVE_CONTROLLED by default), slave CNC_CONTROLLED: LIS510 must not say "use DRIVE_CONTROLLED",
    # which LIS511 reports as refused (P-ERR-50429).
    rows = machine(
        tmp_path,
        {
            "achsmds1.lis": MASTER + "kenngr.antr_typ 2\n",
            "achsmds2.lis": SLAVE + "kenngr.antr_typ 2\nkenngr.homing.homing_type CNC_CONTROLLED\n",
        },
        ["LIS510", "LIS511"],
    )
    assert [row[:3] for row in rows] == [("achsmds1.lis", 1, "LIS511"), ("achsmds2.lis", 6, "LIS510")]
    assert "Use DRIVE_CONTROLLED" not in rows[1][3]
    assert "other than DRIVE_CONTROLLED" in rows[1][3]


def test_drive_controlled_slave_without_its_master_is_judged_alone(tmp_path):
    rows = machine(
        tmp_path,
        {
            "achsmds1.lis": MASTER + "kenngr.antr_typ 2\nkenngr.homing.homing_type CNC_CONTROLLED\n",
            "achsmds2.lis": SLAVE.replace("gantry_ax_nr 1", "gantry_ax_nr 7") + "kenngr.antr_typ 2\n",
        },
        ["LIS503", "LIS510", "LIS511"],
    )
    assert [row[:3] for row in rows] == [("achsmds2.lis", 1, "LIS511"), ("achsmds2.lis", 4, "LIS503")]
    assert "its own type counts" in rows[0][3]


# --- item 6: a DISABLED axis named by G74 is refused (P-AXIS-00299, P-ERR-50686 / P-ERR-60313) -------------------


@pytest.mark.parametrize(
    "absolute,why",
    [
        ("1", "its absolute position is valid without homing: leave it out of G74"),
        ("0", "the axis is incremental (kenngr.abs_pos_gueltig 0), so it can never be homed (LIS308)"),
    ],
)
def test_dry_run_of_a_disabled_axis_says_the_cnc_refuses_g74(absolute, why):
    text = f"kenngr.antr_typ 2\nkenngr.abs_pos_gueltig {absolute}\nkenngr.homing.homing_type DISABLED\n"
    trace = dry_run(listed(text), "d.lis").trace
    assert trace.outcome == "failed" and not trace.phases and trace.reference is None
    assert trace.failure == (
        "homing is DISABLED (kenngr.homing.homing_type): the CNC refuses a G74 that names this axis "
        f"(P-ERR-50686 / P-ERR-60313); {why}"
    )
    # explain says the same of G74 on this axis.
    assert "P-ERR-50686 / P-ERR-60313" in explain_list(listed(text), "d.lis")["strategy"]["description"]


def test_sweep_of_a_disabled_axis_counts_refusals_not_homed_runs():
    from achslint.dryrun import prepare, sweep

    text = "kenngr.antr_typ 2\nkenngr.abs_pos_gueltig 1\nkenngr.homing.homing_type DISABLED\n"
    summary = sweep(prepare(listed(text), "d.lis"), 5)
    assert summary["outcomes"] == {"failed": 5}
    assert "refuses a G74" in summary["reasons"][0]["reason"]


def test_an_absolute_axis_that_may_be_homed_still_needs_no_homing():
    # Only DISABLED refuses: an absolute axis with its drive's default homing type needs none.
    assert (
        dry_run(listed("kenngr.antr_typ 2\nkenngr.abs_pos_gueltig 1\n"), "a.lis").trace.outcome
        == "not_required"
    )

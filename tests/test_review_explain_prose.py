"""Review of what `achslint explain LIST` says about an axis's homing, held against the TF5200 homing
manual: every statement must hold for the axis under its resolved configuration and agree with `lint`."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest

import achslint


def _explain(*lines: str) -> dict[str, Any]:
    return dict(achslint.explain(("\n".join(lines) + "\nEnde\n").encode()))


def _rows(report: dict[str, Any]) -> dict[str, dict[str, Any]]:
    return {row["parameter"]: row for row in report["parameters"]}


def _codes(*lines: str) -> dict[str, list[str]]:
    found: dict[str, list[str]] = {}
    for diagnostic in achslint.lint(("\n".join(lines) + "\nEnde\n").encode()):
        found.setdefault(diagnostic.code, []).append(diagnostic.message)
    return found


TYPE_II = (
    "kenngr.antr_typ 1",
    "kenngr.ref_ohne_nocken 1",
    "kenngr.ref_ohne_rev 1",
    "lr_hw[0].zero_pulse_search_max_dist 50000",
)


def test_type_ii_zero_pulse_search_is_not_counted_from_a_cam_edge() -> None:
    # §2.3.3.3: referencing with zero pulse without reference cam; there is no cam edge and the shift of
    # §2.6 (P-AXIS-00494) has no effect, so the search bound cannot count from "the cam edge plus the shift".
    report = _explain(*TYPE_II)
    assert report["strategy"]["id"] == "zero_pulse_only"
    rows = _rows(report)
    assert rows["kenngr.shift_offset_zero_pulse_activation"]["effective"] is False
    reason = rows["lr_hw[0].zero_pulse_search_max_dist"]["reason"]
    assert rows["lr_hw[0].zero_pulse_search_max_dist"]["effective"] is True
    assert "cam" not in reason.replace("without a cam", "") and "shift_offset" not in reason, reason
    assert "start" in reason


ONE_PHASE = {
    "one_phase_cam": ("kenngr.homing_without_zero_pulse 1",),
    "one_phase_cam_zero_pulse": ("kenngr.homing_without_zero_pulse 0",),
}


@pytest.mark.parametrize("strategy", sorted(ONE_PHASE))
def test_one_phase_homing_does_not_bound_a_move_off_the_cam(strategy: str) -> None:
    # §2.3.3.2 and §3.2.1: without reversal homing runs in a single phase and never moves off the cam, so
    # the bound of the move off the cam (P-AXIS-00531) has nothing to bound; lint says so (LIS401).
    lines = (
        "kenngr.antr_typ 1",
        "kenngr.ref_ohne_nocken 0",
        "kenngr.ref_ohne_rev 1",
        *ONE_PHASE[strategy],
        "lr_hw[0].move_from_cam_max_dist 50000",
    )
    report = _explain(*lines)
    assert report["strategy"]["id"] == strategy
    assert all("off the" not in phase["name"] for phase in report["phases"])
    row = _rows(report)["lr_hw[0].move_from_cam_max_dist"]
    assert row["effective"] is False, row["reason"]
    assert any("move_from_cam_max_dist" in message for message in _codes(*lines).get("LIS401", []))


def test_fixed_stop_without_retraction_distance_describes_no_retraction() -> None:
    # §2.3.3.4.1: after the stop is detected the axis moves away by the retraction distance (P-AXIS-00348);
    # with 0 there is no such move, and the dry-run runs one phase only: explain must not describe a second.
    good = Path(__file__).parent.parent / "fixtures" / "rules" / "LIS306" / "good.lis"
    lines = [
        line
        for line in good.read_bytes().decode("latin-1").splitlines()
        if "retraction" not in line and line.strip() != "Ende"
    ]
    report = _explain(*lines)
    assert report["strategy"]["id"] == "fixed_stop"
    assert _rows(report)["kenngr.homing.torq_retraction_distance"]["value"] == 0
    run = achslint.dry_run(("\n".join(lines) + "\nEnde\n").encode())
    assert [phase["name"] for phase in report["phases"]] == [phase.name for phase in run.trace.phases]
    assert all("retract" not in phase["name"] for phase in report["phases"])


@pytest.mark.xfail(
    strict=True,
    reason="homing/parameters.py EVERYWHERE calls antr.reference_check.* effective on every drive type; "
    "reference monitoring works on SERCOS only (§2.5.1, P-ERR-110548). Giving both Use entries when=SERCOS "
    "is not enough: LIS401 then replaces LIS310's correction finding and the invariants (one finding per "
    "parameter) fail; explain should show the CNC's correction (the name emptied) instead",
)
def test_reference_monitoring_has_no_effect_on_a_drive_other_than_sercos() -> None:
    # §2.5.1: reference monitoring is possible only for the SERCOS drive type; on any other the CNC reports
    # ID 110548 and (LIS310) uses an empty element name, so neither parameter takes effect.
    lines = (
        "kenngr.antr_typ 1",
        "antr.reference_check.element_name S-0-0135",
        "antr.reference_check.bit_nr 6",
    )
    assert "LIS310" in _codes(*lines)
    rows = _rows(_explain(*lines))
    assert rows["antr.reference_check.element_name"]["effective"] is False
    assert rows["antr.reference_check.bit_nr"]["effective"] is False

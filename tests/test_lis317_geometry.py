"""LIS317 on short axes (issue 26 item 9): the geometry the check assumes fits the axis, and when none does the
rule says so instead of passing.

The default cam begins 100 mm from the start; on an axis with software limits -50..50 mm (limit switches
assumed 10 mm beyond them, at ±60 mm) homing ran into the limit switch first, found no reference, and LIS317
checked nothing."""

from __future__ import annotations

import pytest

from achslint import dryrun
from achslint.api import lint_text
from achslint.axis.resolved import resolve_bytes
from achslint.homing.registry import classify
from achslint.homing.scenario import fitted_cams

# Limits -50..50 mm, homing positive, slow speed 50 mm/s, a_ref 100 mm/s²; fast speed vb_refmax default
# 83.333 mm/s.
SHORT = """kopf.achs_nr                 1
kenngr.antr_typ              1
kenngr.swe_neg               -500000
kenngr.swe_pos               500000
kenngr.ref_richt             1
getriebe[0].vb_reflow        50000
getriebe[0].a_ref            100
getriebe[0].pos_refpkt       {refpkt}
lr_hw[0].cam_direct_access   0
Ende
"""

# Homing positive from 0 where the software limit swe_pos is 0: no room for any cam in the homing direction.
NO_ROOM = """kopf.achs_nr                 1
kenngr.antr_typ              1
kenngr.swe_neg               -1000000
kenngr.swe_pos               0
kenngr.ref_richt             1
getriebe[0].a_ref            1000
getriebe[0].pos_refpkt       -100000
lr_hw[0].cam_direct_access   0
Ende
"""


def lis317(text: str) -> list[tuple[str, str]]:
    return [
        (d.severity.value, d.message) for d in lint_text(text, filename="achsmds1.lis", select=["LIS317"])
    ]


def test_fitted_cams_by_hand() -> None:
    # Room from the start 0 to swe_pos 50: 50 mm. Fast braking 83.333²/(2·100) = 34.72 mm, so the default
    # width is 3·34.72 = 104.17 mm. Distances 25, 12.5, 5; widths the default capped at the rest of the room
    # (25, 37.5, 45) and at half of it (12.5, 18.75, 22.5).
    braking = 83.333**2 / 200
    places = fitted_cams(0.0, 1, (-50.0, 50.0), braking)
    assert places == [(25.0, 25.0), (25.0, 12.5), (12.5, 37.5), (12.5, 18.75), (5.0, 45.0), (5.0, 22.5)]
    # Homing negative from 0: the room is 50 to swe_neg, mirrored.
    assert fitted_cams(0.0, -1, (-50.0, 50.0), braking) == places
    # A start on or beyond the limit in the homing direction leaves no room.
    assert fitted_cams(0.0, 1, (-100.0, 0.0), braking) == []
    assert fitted_cams(80.0, -1, (-50.0, 50.0), braking) == []


def test_short_axis_gets_a_fitted_cam_and_a_real_check() -> None:
    # The first fitted cam [25, 50]: the axis reaches it at 70.7 mm/s (√(2·100·25)) and brakes 25 mm more, out
    # of the cam (sampled a cycle late) -> rejected. Next [25, 37.5]: narrower still -> rejected. Then
    # [12.5, 50]: reached at 50 mm/s (√(2·100·12.5)), brakes 12.5 mm to 25 mm, on the cam. Back off, then
    # slowly onto it again: the zero pulse half a period (2.5 mm) after the edge at 15 mm becomes pos_refpkt
    # 45 mm, and the axis brakes 50²/(2·100) = 12.5 mm to 57.5 mm, beyond swe_pos 50 by 7.5 mm: pos_refpkt
    # must move inside by the whole braking distance, 12.5 mm.
    data = SHORT.format(refpkt=450000).encode()
    values = resolve_bytes(data, "achsmds1.lis")
    strategy = classify(values, 0)
    scenario = strategy.default_scenario()
    assert scenario.cam == (12.5, 50.0)
    assert "cam" in scenario.assumed
    assert scenario.limit_switches == (-60.0, 60.0)
    expected = (
        "after braking the axis stands at 57.5 mm, outside the software limits [-50, 50] mm: move the "
        "reference position inside by at least 12.5 mm"
    )
    assert lis317(SHORT.format(refpkt=450000)) == [("warning", expected)]
    # 35 mm + 12.5 mm = 47.5 mm: inside, nothing to report.
    assert lis317(SHORT.format(refpkt=350000)) == []
    # The dry-run assumes the same cam and reports the same fact in the same words.
    trace = dryrun.dry_run(data, "achsmds1.lis").trace
    assert trace.scenario.cam == (12.5, 50.0)
    assert {"code": "LIS317", "message": expected} in trace.warnings


def test_no_fitting_geometry_is_said_not_passed() -> None:
    # Start 0 on swe_pos 0, homing positive: the default cam [100, 120] mm lies beyond the limit switch at
    # 10 mm, and no cam fits between the start and the limit. Fast braking 83.333²/2000 = 3.47 mm, so the
    # default width is 20 mm.
    [(severity, message)] = lis317(NO_ROOM)
    assert severity == "info"
    assert message.startswith("not checked: homing with the assumed cam at [100, 120] mm fails (")
    # The failure names the switch (swe_pos 0 + 10 mm) and what was searched beyond it (issue 26 item 11).
    assert "(to the reference cam: the limit switch at 10 mm was reached before the cam at 100 mm)" in message
    assert "achslint dry-run --scenario" in message
    # The dry-run keeps that cam and fails at the limit switch, as the finding says.
    trace = dryrun.dry_run(NO_ROOM.encode(), "achsmds1.lis").trace
    assert trace.scenario.cam == (100.0, 120.0)
    assert trace.outcome == "failed"
    assert trace.failure is not None and trace.failure in message


@pytest.mark.parametrize("refpkt", [450000, 350000])
def test_long_axis_keeps_the_default_cam(refpkt: int) -> None:
    # Limits -1000..1000 mm: the default cam 100 mm away fits and stays (no fitting on axes long enough).
    text = SHORT.format(refpkt=refpkt).replace("-500000", "-10000000").replace(" 500000", " 10000000")
    strategy = classify(resolve_bytes(text.encode(), "achsmds1.lis"), 0)
    # Width three fast braking distances: 3·83.333²/(2·100) = 104.166 mm.
    assert strategy.default_scenario().cam == pytest.approx((100.0, 100.0 + 3 * 83.333**2 / 200))


def test_not_checked_is_an_info_the_rule_documents() -> None:
    # The simulated drive's default geometry leaves no room for any assumed cam: LIS317 says it could not
    # check, as an info finding, and the rule's documentation names that severity (the invariant tests
    # compare every emitted severity with the documented ones).
    from achslint.core.diagnostics import Severity
    from achslint.docs import rule_text
    from achslint.rules import registry

    found = [d for d in lint_text("kenngr.antr_typ 1\nlr_hw[0].cam_level 0\nEnde\n") if d.code == "LIS317"]
    assert [d.severity for d in found] == [Severity.INFO]
    rule = registry()["LIS317"]
    assert rule.severities == (Severity.WARNING, Severity.INFO)
    assert "warning by default; info when it cannot check" in rule_text(rule)

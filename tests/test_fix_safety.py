"""A safe fix keeps what the machine does: the resolved axis changes only in the corrected finding, and no
new finding appears. Otherwise the fix is unsafe (applied only with --unsafe-fixes)."""

from __future__ import annotations

from collections import Counter

import pytest

from achslint.linting.fixer import behaviour, fix_bytes
from achslint.linting.linter import lint_file

from .conftest import FIXTURES
from .fixture_lists import distinct_lists


def fixes(data: bytes) -> dict[str, str]:
    """code -> applicability of the fixes offered after the fixer looked at them."""
    return {d.code: d.fix.applicability for d in fix_bytes(data, "x.lis").result.diagnostics if d.fix}


def test_symbol_typo_into_a_homing_type_the_drive_cannot_run_is_unsafe():
    # A conventional drive (1) cannot home drive-controlled: the CNC would replace the value (LIS305).
    data = b"kenngr.antr_typ 1\nkenngr.homing.homing_type DRIVE_CONROLLED\nEnde\n"
    assert fix_bytes(data, "x.lis").data == data
    assert fixes(data)["LIS203"] == "unsafe"
    assert b"DRIVE_CONTROLLED" in fix_bytes(data, "x.lis", unsafe=True).data


def test_symbol_typo_into_a_supported_value_stays_safe():
    data = b"kenngr.antr_typ 1\nkenngr.homing.homing_type CNC_CONROLLED\nEnde\n"
    assert (
        fix_bytes(data, "x.lis").data
        == b"kenngr.antr_typ 1\nkenngr.homing.homing_type CNC_CONTROLLED\nEnde\n"
    )


def test_a_name_fix_that_switches_on_an_ignored_parameter_is_unsafe():
    data = b"kenngr.ref_ricth 1\nEnde\n"  # the CNC ignores the misspelt line; ref_richt would become 1
    assert fix_bytes(data, "x.lis").data == data
    assert fixes(data)["LIS101"] == "unsafe"


def test_a_name_fix_that_writes_the_value_the_cnc_already_uses_is_safe():
    default = behaviour(b"Ende\n", "x.lis")  # nothing set
    assert default == {}
    data = b"kenngr.ref_ricth 0\nEnde\n"  # 0 is ref_richt's default: the fix changes nothing the CNC does
    assert fix_bytes(data, "x.lis").data == b"kenngr.ref_richt 0\nEnde\n"


# One of each distinct fixture list: a copy (same bytes and name) would repeat the same test.
@pytest.mark.parametrize("path", distinct_lists(), ids=lambda p: str(p.relative_to(FIXTURES)))
def test_safe_fixes_over_every_fixture_keep_behaviour_and_add_no_finding(path):
    data = path.read_bytes()
    before = lint_file(data, path.name)
    if before.error:
        return
    outcome = fix_bytes(data, path.name)
    if outcome.data == data:
        return  # nothing fixed (most fixtures): the same bytes lint and behave as `before` says
    after = lint_file(outcome.data, path.name)
    assert after.error is None
    new = Counter((d.code, d.parameter) for d in after.diagnostics) - Counter(
        (d.code, d.parameter) for d in before.diagnostics
    )
    assert not new, new
    fixed_parameters = {d.parameter for d in before.diagnostics if d.fix is not None}
    was, now = behaviour(data, path.name), behaviour(outcome.data, path.name)
    changed = {p for p in was.keys() | now.keys() if was.get(p) != now.get(p)}
    assert changed <= fixed_parameters, changed

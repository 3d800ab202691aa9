"""`lint --fix`: fixes repair what they claim, respect suppressions, and leave nothing for a second run."""

from __future__ import annotations

import pytest

from achslint.linting.fixer import fix_bytes
from achslint.linting.linter import FileSettings

from .conftest import FIXTURES

SAFE = ["LIS002", "LIS004", "LIS006", "LIS102", "LIS203"]  # LIS101's fixture fixes change behaviour: unsafe


@pytest.mark.parametrize("code", SAFE)
def test_safe_fix_removes_the_finding_and_is_stable(code):
    data = (FIXTURES / "rules" / code / "bad.lis").read_bytes()
    settings = FileSettings.of([code])
    outcome = fix_bytes(data, "bad.lis", settings)
    assert outcome.fixed >= 1
    remaining = [d for d in outcome.result.diagnostics if d.code == code]
    assert all(d.fix is None or d.fix.applicability != "safe" for d in remaining)
    again = fix_bytes(outcome.data, "bad.lis", settings)
    assert again.fixed == 0 and again.data == outcome.data


def test_fixes_change_only_what_they_claim():
    data = (
        b"kopf.achs_nr 1\nkenngr.ref_ricth 1 ( keep this comment\nkenngr.homing_type DRIVE_CONROLLED\nEnd\n"
    )
    outcome = fix_bytes(
        data, "x.lis"
    )  # the typos change what the CNC does (tests/test_fix_safety.py): unsafe
    assert outcome.data == (
        b"kopf.achs_nr 1\nkenngr.ref_ricth 1 ( keep this comment\n"
        b"kenngr.homing.homing_type DRIVE_CONROLLED\nEnde\n"
    )
    assert outcome.fixed == 2  # old name, end marker
    outcome = fix_bytes(data, "x.lis", unsafe=True)
    assert outcome.data == (
        b"kopf.achs_nr 1\nkenngr.ref_richt 1 ( keep this comment\n"
        b"kenngr.homing.homing_type DRIVE_CONTROLLED\nEnde\n"
    )
    assert outcome.fixed == 4  # typo, old name, symbol typo, end marker


def test_bom_removal_and_latin1_kept():
    data = b"\xef\xbb\xbfkopf.achs_nr 1 ( \xb5m\nEnde\n"
    outcome = fix_bytes(data, "x.lis")
    assert outcome.data == b"kopf.achs_nr 1 ( \xb5m\nEnde\n"


def test_suppressed_diagnostics_are_not_fixed():
    data = b"kenngr.homing_type CNC_CONTROLLED # noqa: LIS102\nEnd\n"
    outcome = fix_bytes(data, "x.lis")
    assert outcome.data == b"kenngr.homing_type CNC_CONTROLLED # noqa: LIS102\nEnde\n"


def test_unsafe_fixes_only_when_asked():
    data = b"getriebe[0].vb_refmax 100000.0\nEnde\n"
    assert fix_bytes(data, "x.lis").data == data
    assert fix_bytes(data, "x.lis", unsafe=True).data == b"getriebe[0].vb_refmax 100000\nEnde\n"


def test_missing_end_marker_is_appended_with_the_files_line_break():
    assert fix_bytes(b"a 1\r\nb 2\r\n", "x.lis").data == b"a 1\r\nb 2\r\nEnde\r\n"
    assert fix_bytes(b"a 1\nb 2", "x.lis").data == b"a 1\nb 2\nEnde\n"


def test_cli_fix_diff_and_stdin(cli, tmp_path):
    path = tmp_path / "achsmds1.lis"
    original = b"kenngr.homing_type CNC_CONTROLLED\nEnd\n"
    path.write_bytes(original)
    diff = cli("lint", "--fix", "--diff", str(path))
    assert b"+Ende" in diff.stdout and path.read_bytes() == original
    fixed = cli("lint", "--fix", str(path), "--format", "concise")
    assert path.read_bytes() == b"kenngr.homing.homing_type CNC_CONTROLLED\nEnde\n"
    assert b"fixed 2 diagnostics" in fixed.stderr
    assert cli("lint", "--fix", str(path)).stderr.startswith(b"fixed 0 diagnostics")
    piped = cli("lint", "--fix", "-", stdin=b"End\n")
    assert piped.stdout == b"Ende\n"
    path.write_bytes(original)
    alone = cli("lint", "--diff", str(path))  # as in ruff, --diff alone shows what --fix would change
    assert b"+Ende" in alone.stdout and path.read_bytes() == original

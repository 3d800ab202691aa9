"""Review of what achslint prints and returns: formats that disagree with each other or with their
consumers, and library calls that accept what the command line refuses."""

from __future__ import annotations

import json
import xml.etree.ElementTree as ET

import pytest

import achslint

from .conftest import FIXTURES

LIS204_BAD = FIXTURES / "rules" / "LIS204" / "bad.lis"
AXIS = FIXTURES / "lists" / "achsmds1.lis"


def sarif_results(cli, *args: str) -> list[dict]:
    result = cli("lint", *args, "--format", "sarif", "--exit-zero")
    assert result.returncode == 0, result.stderr
    return json.loads(result.stdout)["runs"][0]["results"]


def test_sarif_fingerprints_tell_repeated_findings_of_one_parameter_apart(cli, tmp_path):
    """Four LIS204 (and three LIS005) findings on `kenngr.achs_mode` in one file had one fingerprint each:
    code scanning takes results with the same partial fingerprint for one alert and shows only one."""
    results = sarif_results(cli, str(LIS204_BAD))
    prints = [r["partialFingerprints"]["achslint/v1"] for r in results]
    assert len(results) == 7
    assert len(set(prints)) == len(prints)
    # Still stable when lines move: the same file with a comment line on top has the same fingerprints.
    moved = tmp_path / "bad.lis"
    moved.write_bytes(b"# a new first line\n" + LIS204_BAD.read_bytes())
    again = sarif_results(cli, str(moved))
    assert [r["partialFingerprints"]["achslint/v1"] for r in again] == [
        r["partialFingerprints"]["achslint/v1"]
        for r in sarif_results(cli, str(tmp_path / "bad.lis"))  # same path: fingerprints include it
    ]
    assert [r["locations"][0]["physicalLocation"]["region"]["startLine"] for r in again] == [
        r["locations"][0]["physicalLocation"]["region"]["startLine"] + 1 for r in results
    ]


def test_sarif_first_fingerprint_of_a_kind_is_unchanged(cli, tmp_path):
    """Telling repeats apart must not move the fingerprint of a finding that occurs once (existing alerts)."""
    import hashlib

    results = sarif_results(cli, str(LIS204_BAD))
    first = results[0]
    assert first["ruleId"] == "LIS204"
    key = f"LIS204\0{LIS204_BAD}\0kenngr.achs_mode".encode()
    assert first["partialFingerprints"]["achslint/v1"] == hashlib.sha256(key).hexdigest()[:32]


def test_sarif_says_its_columns_count_code_points(cli, tmp_path):
    """Columns count characters (code points); SARIF readers assume UTF-16 code units unless the run says
    otherwise, which puts every column after a character beyond the BMP one too far."""
    listed = tmp_path / "achsmds1.lis"
    listed.write_bytes(
        'kopf.achs_nr 1\nkopf.log_achs_name "X\U0001f600" trailing\nkenngr.achs_mode 0x1\n'
        "kenngr.achs_typ 1\nEnde\n".encode()
    )
    document = json.loads(cli("lint", str(listed), "--format", "sarif").stdout)
    run = document["runs"][0]
    assert run["columnKind"] == "unicodeCodePoints"
    concise = cli("lint", str(listed), "--format", "concise").stdout.decode()
    column = int(concise.split(":")[2])
    region = run["results"][0]["locations"][0]["physicalLocation"]["region"]
    assert region["startColumn"] == column == 25


def test_junit_totals_count_an_unreadable_file_as_an_error_not_a_failure(cli, tmp_path):
    """The suite of a file that could not be read says errors=1 failures=0; the totals said failures=1 and
    had no errors at all, so the report disagreed with itself."""
    (tmp_path / "achsmds1.lis").write_bytes("kopf.achs_nr 1\nEnde\n".encode("utf-16"))
    (tmp_path / "achsmds2.lis").write_bytes((FIXTURES / "lists" / "achsmds2.lis").read_bytes())
    result = cli("lint", str(tmp_path), "--format", "junit")
    assert result.returncode == 2
    root = ET.fromstring(result.stdout.decode().split("\n", 1)[1])
    suites = root.findall("testsuite")
    for attribute in ("tests", "failures", "errors"):
        assert int(root.get(attribute)) == sum(int(s.get(attribute)) for s in suites), attribute
    assert root.get("errors") == "1" and root.get("failures") == "0"


@pytest.mark.parametrize("gear", [6, 9, -1])
def test_explain_and_dry_run_refuse_a_gear_stage_that_does_not_exist(gear):
    """`--gear` takes 0..5 on the command line; the library explained `getriebe[9]` from defaults as if it
    existed, and gear -1 ended in a KeyError about a catalogue parameter."""
    with pytest.raises(ValueError, match=r"gear.*0 to 5"):
        achslint.explain(AXIS, gear=gear)
    with pytest.raises(ValueError, match=r"gear.*0 to 5"):
        achslint.dry_run(AXIS, gear=gear)


def test_explain_and_dry_run_take_every_gear_stage():
    for gear in range(6):
        assert achslint.explain(AXIS, gear=gear)["gear"] == gear
        assert achslint.dry_run(AXIS, gear=gear).trace.outcome == "homed"


def test_lint_paths_of_a_folder_without_lists_is_an_error_as_on_the_command_line(cli, tmp_path):
    """`achslint lint EMPTY` exits 2 (a CI job pointed at the wrong folder must not pass); the library
    returned an empty list, which reads as `no findings`."""
    (tmp_path / "notes.txt").write_text("nothing here\n")
    assert cli("lint", str(tmp_path)).returncode == 2
    with pytest.raises(achslint.LintFailed, match="no axis list found"):
        achslint.lint_paths([tmp_path])
    with pytest.raises(achslint.LintFailed, match="no axis list found"):
        achslint.lint(tmp_path)
    assert achslint.lint_paths([tmp_path], allow_empty=True) == []


def test_lint_of_an_nc_program_is_refused_as_on_the_command_line(cli):
    """`achslint lint rfp.nc` exits 2 (a program is checked against a machine: --machine); the library
    linted the program as an axis list: LIS001 for `%RFP.NC`, LIS101 for every block number."""
    program = FIXTURES / "rules" / "LIS601" / "bad.nc"
    assert cli("lint", str(program)).returncode == 2
    with pytest.raises(achslint.LintFailed, match="NC program"):
        achslint.lint(program)
    with pytest.raises(achslint.LintFailed, match="NC program"):
        achslint.lint(str(program))

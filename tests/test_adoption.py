"""Gradual adoption like ruff (issue 27 item 4): `rules --format json`, `--show-files`, `--show-settings`,
`extend`, `fixable`/`unfixable`, `--add-noqa` and `--watch`."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from achslint.rules import registry

from .conftest import FIXTURES, one_machine


def test_rules_json_lists_every_rule_as_the_table_and_rule_do(cli):
    result = cli("rules", "--format", "json")
    assert result.returncode == 0
    rules = json.loads(result.stdout)
    assert [rule["code"] for rule in rules] == list(registry())
    table = {line.split()[0]: line.split()[1:4] for line in cli("rules").stdout.decode().splitlines()[2:]}
    for rule in rules:
        assert table[rule["code"]] == [rule["name"], rule["severity"], rule["fix"]]
        assert rule["url"].endswith("#" + rule["code"].lower())
        assert set(rule["scopes"]) <= {"list", "machine", "program", "after"}
        assert bool(rule["scopes"]) == (rule["produced_by"] == "lint"), rule["code"]
    by_code = {rule["code"]: rule for rule in rules}
    assert by_code["LIS202"]["explanation"] == cli("rule", "LIS202").stdout.decode().rstrip("\n")
    assert by_code["LIS501"]["scopes"] == ["machine"] and by_code["LIS501"]["lists"] is None


def repository(tmp_path: Path) -> Path:
    """A folder that is a git work tree (where `extend` may lead), with a list in `machine/`."""
    (tmp_path / ".git").mkdir()
    (tmp_path / "machine").mkdir()
    (tmp_path / "machine" / "achsmds1.lis").write_bytes(END_LIST)
    return tmp_path


# `End` (LIS004, safe fix: Ende) and an unknown parameter (LIS101 with a safe rename)
END_LIST = b"kopf.achs_nr  1\nkenngr.ref_ricth  1\nEnd\n"


def codes(result) -> list[str]:
    return [line.split()[1] for line in result.stdout.decode().splitlines() if ": LIS" in line]


def test_extend_builds_on_a_base_relative_to_the_file(cli, tmp_path: Path):
    root = repository(tmp_path)
    (root / "base.toml").write_text(
        'ignore = ["LIS101"]\nfail-on = "warning"\ncnc-root = "machine"\n[severity]\nLIS004 = "error"\n'
    )
    (root / "machine" / "achslint.toml").write_text(
        'extend = "../base.toml"\nignore = ["LIS002"]\n[severity]\nLIS009 = "error"\n'
    )
    shown = json.loads(cli("config", "--show", str(root / "machine")).stdout.decode().split("\n", 1)[1])
    assert shown["extend"] == "../base.toml"
    assert shown["ignore"] == ["LIS101", "LIS002"]  # lists the command line extends add up
    assert shown["severity"] == {"LIS004": "error", "LIS009": "error"}  # tables merge key by key
    assert shown["fail-on"] == "warning"  # the rest comes from the base unless the file sets it
    assert shown["cnc-root"] == "."  # still the folder the base named
    result = cli("lint", str(root / "machine" / "achsmds1.lis"), "--format", "concise")
    assert codes(result) == ["LIS004"] and "[error]" in result.stdout.decode()


def test_the_extending_file_wins(cli, tmp_path: Path):
    root = repository(tmp_path)
    (root / "base.toml").write_text('select = ["LIS101"]\nfail-on = "info"\n')
    (root / "machine" / "achslint.toml").write_text('extend = "../base.toml"\nselect = ["LIS004"]\n')
    result = cli("lint", str(root / "machine" / "achsmds1.lis"), "--format", "concise")
    assert codes(result) == ["LIS004"] and result.returncode == 1  # LIS004 warning, fail-on info


def test_extend_chains_and_its_errors_name_file_and_key(cli, tmp_path: Path):
    root = repository(tmp_path)
    config = root / "machine" / "achslint.toml"
    (root / "base.toml").write_text('extend = "common/base.toml"\n')
    (root / "common").mkdir()
    (root / "common" / "base.toml").write_text('ignore = ["LIS4"]\n')
    config.write_text('extend = "../base.toml"\n')
    assert json.loads(cli("config", "--show", str(config)).stdout.decode().split("\n", 1)[1])["ignore"] == [
        "LIS4"
    ]
    cases = {
        '"machine/achslint.toml"': f"configuration error in {root / 'base.toml'}: key `extend`: "
        "'machine/achslint.toml' extends in a circle",
        '"missing.toml"': f"configuration error in {root / 'base.toml'}: key `extend`: 'missing.toml'",
        '"../../elsewhere.toml"': "lies outside",
        "5": "key `extend`: Input should be a valid string",
    }
    for value, said in cases.items():
        (root / "base.toml").write_text(f"extend = {value}\n")
        result = cli("lint", str(root / "machine" / "achsmds1.lis"))
        assert result.returncode == 2, value
        assert said in result.stderr.decode() and result.stderr.decode().count("\n") == 1, value
    (root / "base.toml").write_text('fail-on = "never"\n')  # an error in the base names the base
    assert (
        f"configuration error in {root / 'base.toml'}: key `fail-on`"
        in cli("lint", str(root / "machine")).stderr.decode()
    )


def test_unfixable_and_fixable_decide_what_fix_may_fix(cli, tmp_path: Path):
    root = repository(tmp_path)
    config = root / "machine" / "achslint.toml"
    target = root / "machine" / "achsmds1.lis"
    bom = b"\xef\xbb\xbf"  # LIS006, and End (LIS004): both with safe fixes
    listed = bom + b"kopf.achs_nr  1\nEnd\n"
    target.write_bytes(listed)
    config.write_text('unfixable = ["LIS004"]\n')
    fixes = {
        d["code"]: d["fix"]
        for d in json.loads(cli("lint", str(target), "--format", "json").stdout)["diagnostics"]
    }
    assert fixes["LIS004"] is None and fixes["LIS006"] is not None
    cli("lint", str(target), "--fix")
    assert target.read_bytes() == listed.removeprefix(bom)  # End stays
    target.write_bytes(listed)
    config.write_text('fixable = ["LIS004"]\n')
    cli("lint", str(target), "--fix")
    assert target.read_bytes() == listed.replace(b"End", b"Ende")  # the BOM stays
    config.write_text('fixable = ["LIS0"]\nunfixable = ["LIS0"]\n')
    target.write_bytes(listed)
    result = cli("lint", str(target), "--fix")
    assert target.read_bytes() == listed and "fixed 0 diagnostics" in result.stderr.decode()
    assert "fixable with --fix" not in cli("lint", str(target)).stdout.decode()
    config.write_text("fixable = []\n")  # as in ruff: an empty list fixes nothing
    target.write_bytes(listed)
    cli("lint", str(target), "--fix")
    assert target.read_bytes() == listed
    config.write_text("")
    assert "2 fixable with --fix" in cli("lint", str(target)).stdout.decode()


# --add-noqa -------------------------------------------------------------------------------------------

# A list in `(` comment style with findings on assignments (a number, a symbol), one already suppressed
# for another code, one with a comment, and the missing `Ende` (a file-level finding); Latin-1 and CRLF.
LEGACY = (
    b"kopf.achs_nr                 1   ( logical axis \xb5\r\n"
    b"kenngr.ref_ricth             1\r\n"
    b"kenngr.homing.homing_type    DRIVE_CONROLLED\r\n"
    b"getriebe[6].vb_refmax        100000  ( noqa: LIS203\r\n"
    b"kenngr.homing_typ            1   ( fast\r\n"
)


def lint_codes(cli, path: Path) -> list[str]:
    return codes(cli("lint", str(path), "--format", "concise"))


def test_add_noqa_suppresses_every_finding_losslessly_and_once(cli, tmp_path: Path):
    target = tmp_path / "achsmds1.lis"
    target.write_bytes(LEGACY)
    before = lint_codes(cli, target)
    assert {"LIS101", "LIS203", "LIS104", "LIS002"} <= set(before)
    result = cli("lint", str(target), "--add-noqa")
    assert result.returncode == 0, result.stderr
    # the stale `noqa: LIS203` of line 4 stays a finding (LIS009): removed, not suppressed
    assert result.stderr.decode().startswith("added 5 noqa directives; 1 finding left")
    after = target.read_bytes()
    assert after.splitlines(keepends=True) == [
        b"# achslint: noqa: LIS002\r\n",  # the finding of no line: for the file, in the file's line break
        b"kopf.achs_nr                 1   ( logical axis \xb5\r\n",  # Latin-1 kept
        b"kenngr.ref_ricth             1  ( noqa: LIS101\r\n",  # in the list's style: `(`
        b"kenngr.homing.homing_type    DRIVE_CONROLLED  ( noqa: LIS203\r\n",
        b"getriebe[6].vb_refmax        100000  ( noqa: LIS203, LIS104\r\n",  # merged into the existing one
        b"kenngr.homing_typ            1   ( fast  noqa: LIS101\r\n",  # into the line's comment
    ]
    assert lint_codes(cli, target) == ["LIS009"]
    again = cli("lint", str(target), "--add-noqa")
    assert target.read_bytes() == after and "added 0 noqa directives" in again.stderr.decode()


def test_add_noqa_writes_hash_comments_in_a_hash_style_list(cli, tmp_path: Path):
    target = tmp_path / "achsmds1.lis"
    target.write_bytes(
        b"kopf.achs_nr  1  # axis\nkenngr.ref_ricth  1\nkenngr.homing.homing_type  DRIVE_CONROLLED\nEnde\n"
    )
    cli("lint", str(target), "--add-noqa")
    assert target.read_bytes().splitlines()[1:3] == [
        b"kenngr.ref_ricth  1  # noqa: LIS101",
        b"kenngr.homing.homing_type  DRIVE_CONROLLED  ( noqa: LIS203",  # after text only `(` is a comment
    ]
    assert lint_codes(cli, target) == []


def test_add_noqa_leaves_machine_findings_and_xml_alone(cli, tmp_path: Path):
    for name in ("achsmds1.lis", "achsmds2.lis"):  # one logical axis number twice: LIS501, a machine rule
        (tmp_path / name).write_bytes(
            b"kopf.achs_nr  1\nkopf.log_achs_name  X" + name[7:8].encode() + b"\nEnde\n"
        )
    one_machine(tmp_path)
    xml = tmp_path / "ax_mds_1.xml"
    xml.write_bytes(
        (FIXTURES / "rules" / "LIS203" / "bad.lis").read_bytes().join([b"<AX_MDS><![CDATA[", b"]]></AX_MDS>"])
    )
    before = {path.name: path.read_bytes() for path in tmp_path.iterdir()}
    result = cli("lint", str(tmp_path), "--include", "*.lis", "--add-noqa")
    assert result.returncode == 0
    assert {path.name: path.read_bytes() for path in tmp_path.iterdir()} == before
    assert "1 finding left that a noqa in the list cannot suppress" in result.stderr.decode()


def test_add_noqa_takes_no_standard_input_and_no_fix(cli):
    assert cli("lint", "-", "--add-noqa", stdin=b"Ende\n").returncode == 2
    result = cli("lint", str(FIXTURES / "lists"), "--add-noqa", "--fix")
    assert result.returncode == 2 and "--fix and --add-noqa do not go together" in result.stderr.decode()


# --show-files, --show-settings ---------------------------------------------------------------------------


def test_show_files_lists_what_lint_would_check(cli):
    sdk = FIXTURES / "machines" / "sdk"
    result = cli("lint", str(sdk), "--show-files")
    assert result.returncode == 0
    rows = [line.split("\t") for line in result.stdout.decode().splitlines()]
    startup = str(sdk / "listen" / "hochlauf.lis")
    assert rows[0] == [startup, "startup", startup]
    kinds = [kind for _, kind, _ in rows]
    assert kinds.count("axis") == 3 and kinds.count("default_axis") == 1
    linted = json.loads(cli("lint", str(sdk), "--format", "json", "--exit-zero").stdout)
    assert {d["path"] for d in linted["diagnostics"]} <= {name for name, _, _ in rows}
    assert all(machines == startup for _, _, machines in rows)


def test_show_files_names_the_kind_told_by_content(cli, tmp_path: Path):
    (tmp_path / "kanal.lis").write_bytes((FIXTURES / "kinds" / "sda_mds1.lis").read_bytes())
    (tmp_path / "achsmds1.lis").write_bytes(b"kopf.achs_nr 1\nEnde\n")
    rows = cli("lint", str(tmp_path / "kanal.lis"), str(tmp_path / "achsmds1.lis"), "--show-files").stdout
    assert rows.decode().splitlines() == [
        f"{tmp_path / 'kanal.lis'}\tchannel\t-",
        f"{tmp_path / 'achsmds1.lis'}\taxis\t-",
    ]


def test_show_settings_prints_what_a_run_uses_as_toml_or_json(cli, tmp_path: Path):
    root = repository(tmp_path)
    (root / "base.toml").write_text('cnc-root = "machine"\n[severity]\nLIS004 = "error"\n')
    (root / "machine" / "achslint.toml").write_text('extend = "../base.toml"\nignore = ["LIS2"]\n')
    target = str(root / "machine" / "achsmds1.lis")
    shown = cli("lint", target, "--show-settings", "--ignore", "LIS3").stdout.decode()
    assert shown.splitlines()[:2] == [
        f"# configuration: {root / 'machine' / 'achslint.toml'}",
        f"# extends: {root / 'base.toml'}",
    ]
    copy = root / "machine" / "copy.toml"
    copy.write_text(shown)  # valid TOML, and a configuration that gives the same settings
    from achslint.linting.config import Settings, load_file

    settings = load_file(copy).settings
    assert settings.ignore == ["LIS2", "LIS3"] and settings.severity == {"LIS004": "error"}
    assert settings.cnc_root == "." and settings.extend == "../base.toml"
    assert settings.as_file_keys() == {
        **Settings().as_file_keys(),
        **{
            key: value
            for key, value in json.loads(
                cli("lint", target, "--show-settings", "--ignore", "LIS3", "--format", "json").stdout
            )["settings"].items()
            if key != "extend"
        },
        "extend": "../base.toml",
    }


# --watch -------------------------------------------------------------------------------------------------


@pytest.mark.slow  # runs a real process (the slow tier: .ci/run, `pytest -m slow`)
def test_watch_lints_again_when_a_list_changes(tmp_path: Path):
    """The real entry point in a child process, polling every 20 ms: a report, a change, a second report;
    then it is terminated (about half a second in all, most of it the interpreter starting)."""
    import os
    import select
    import subprocess
    import sys
    import time

    target = tmp_path / "achsmds1.lis"
    target.write_bytes(b"kopf.achs_nr  1\nEnd\n")  # LIS004
    env = {**os.environ, "ACHSLINT_WATCH_INTERVAL": "0.02", "NO_COLOR": "1"}
    child = subprocess.Popen(
        [sys.executable, "-m", "achslint", "lint", str(tmp_path), "--watch", "--format", "concise"],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        env=env,
    )
    said = b""

    def until_watching(times: int) -> None:
        nonlocal said
        deadline = time.monotonic() + 20
        while said.count(b"watching for changes") < times:
            assert time.monotonic() < deadline, said
            ready, _, _ = select.select([child.stderr], [], [], 0.1)
            if ready:
                chunk = os.read(child.stderr.fileno(), 4096)
                assert chunk, said  # it ended
                said += chunk

    try:
        until_watching(1)
        target.write_bytes(b"kopf.achs_nr  1\nkenngr.ref_ricth  1\nEnd\n")  # and LIS101
        until_watching(2)
    finally:
        child.terminate()
        out, _ = child.communicate(timeout=10)
    reports = [line.split()[1] for line in out.decode().splitlines() if ": LIS" in line]
    assert reports == ["LIS004", "LIS101", "LIS004"]
    assert child.returncode != 0  # ended by the signal, not by itself


def test_watch_takes_no_standard_input(cli):
    result = cli("lint", "-", "--watch", stdin=b"Ende\n")
    assert result.returncode == 2 and "--watch" in result.stderr.decode()

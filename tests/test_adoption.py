"""Gradual adoption like ruff (issue 27 item 4): `rules --format json`, `--show-files`, `--show-settings`,
`extend`, `fixable`/`unfixable`, `--add-noqa` and `--watch`."""

from __future__ import annotations

import json
from pathlib import Path

from achslint.rules import registry


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
    config.write_text("")
    assert "2 fixable with --fix" in cli("lint", str(target)).stdout.decode()

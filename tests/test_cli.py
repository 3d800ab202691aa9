"""The real entry point (`python -m achslint`), real files on disk, exit codes."""

from __future__ import annotations

import json

from .conftest import FIXTURES


def test_bundled_lists_lint_clean(cli):
    """The bundled lists are correct: no syntax or name findings, nothing above info."""
    result = cli("lint", str(FIXTURES / "lists"), "--format", "json")
    assert result.returncode == 0, result.stdout.decode() + result.stderr.decode()
    document = json.loads(result.stdout)
    assert document["summary"]["files"] == 3
    assert (document["summary"]["errors"], document["summary"]["warnings"]) == (0, 0)
    assert not [d for d in document["diagnostics"] if d["code"] in ("LIS001", "LIS101")]


def test_errors_give_exit_1_and_concise_lines(cli):
    bad = FIXTURES / "rules" / "LIS202" / "bad.lis"
    result = cli("lint", str(bad), "--format", "concise")
    assert result.returncode == 1
    lines = result.stdout.decode().splitlines()
    assert any(line.startswith(f"{bad}:5:48: LIS202 [error]") for line in lines), lines
    assert result.stderr == b""


def test_warnings_only_pass_unless_fail_on_warning(cli):
    bad = FIXTURES / "rules" / "LIS002" / "bad.lis"
    assert cli("lint", str(bad)).returncode == 0
    assert cli("lint", str(bad), "--fail-on", "warning").returncode == 1
    assert cli("lint", str(bad), "--fail-on", "warning", "--exit-zero").returncode == 0


def test_select_and_ignore(cli):
    bad = FIXTURES / "rules" / "LIS202" / "bad.lis"
    only = cli("lint", str(bad), "--format", "json", "--select", "LIS2")
    codes = {d["code"] for d in json.loads(only.stdout)["diagnostics"]}
    assert codes == {"LIS202"}
    ignored = cli("lint", str(bad), "--format", "json", "--ignore", "LIS202,LIS005")
    assert json.loads(ignored.stdout)["diagnostics"] == []
    assert ignored.returncode == 0


def test_json_shape(cli):
    bad = FIXTURES / "rules" / "LIS101" / "bad.lis"
    result = cli("lint", str(bad), "--format", "json")
    document = json.loads(result.stdout)
    assert document["version"] == 1
    assert document["summary"] == {"files": 1, "errors": 0, "warnings": 4, "infos": 0, "unreadable": []}
    first = document["diagnostics"][0]
    assert set(first) >= {
        "path",
        "line",
        "column",
        "end_line",
        "end_column",
        "code",
        "severity",
        "message",
        "parameter",
        "p_axis",
        "related",
        "fix",
        "url",
    }
    assert (first["line"], first["column"], first["end_column"]) == (5, 1, 17)
    assert first["fix"]["applicability"] == "safe"
    assert first["fix"]["edits"] == [
        {"line": 5, "column": 1, "end_line": 5, "end_column": 17, "content": "kenngr.ref_richt"}
    ]


def test_full_format_shows_code_frame_with_caret(cli):
    bad = FIXTURES / "rules" / "LIS203" / "bad.lis"
    out = cli("lint", str(bad), "--format", "full").stdout.decode()
    assert "LIS203 error:" in out
    assert "5 │ kenngr.homing.homing_type         DRIVE_CONROLLED" in out
    assert "  │ " + " " * 34 + "^" * len("DRIVE_CONROLLED") in out
    assert "\x1b[" not in out  # NO_COLOR


def test_full_format_colours_only_when_asked(cli):
    bad = FIXTURES / "rules" / "LIS203" / "bad.lis"
    out = cli("lint", str(bad), "--format", "full", "--color", "always", env={"NO_COLOR": ""}).stdout.decode()
    assert "\x1b[" in out


def test_stdin_with_filename(cli):
    data = (FIXTURES / "rules" / "LIS201" / "bad.lis").read_bytes()
    result = cli("lint", "-", "--stdin-filename", "axes/achsmds7.lis", "--format", "concise", stdin=data)
    assert result.returncode == 1
    assert result.stdout.decode().startswith("axes/achsmds7.lis:5:49: LIS201")


def test_directory_search_uses_include_pattern(cli, tmp_path):
    (tmp_path / "sub").mkdir()
    (tmp_path / "sub" / "ACHSMDS2.LIS").write_bytes(b"kenngr.ref_richt 2\nEnde\n")
    (tmp_path / "notes.lis").write_bytes(b"kenngr.ref_richt 2\nEnde\n")
    result = cli("lint", str(tmp_path), "--format", "json")
    paths = {d["path"] for d in json.loads(result.stdout)["diagnostics"]}
    assert paths == {str(tmp_path / "sub" / "ACHSMDS2.LIS")}


def test_missing_path_is_exit_2_with_one_line(cli, tmp_path):
    result = cli("lint", str(tmp_path / "nope.lis"))
    assert result.returncode == 2
    assert result.stderr.decode().strip() == f"achslint: {tmp_path / 'nope.lis'}: no such file or directory"
    assert b"Traceback" not in result.stderr


def test_utf16_input_is_exit_2(cli, tmp_path):
    path = tmp_path / "achsmds1.lis"
    path.write_bytes("kopf.achs_nr 1\nEnde\n".encode("utf-16"))
    result = cli("lint", str(path))
    assert result.returncode == 2
    assert b"UTF-16" in result.stderr and b"Traceback" not in result.stderr


def test_bad_option_is_usage_error(cli):
    result = cli("lint", "--fail-on", "sometimes", str(FIXTURES / "lists"))
    assert result.returncode == 2


def test_rule_docs_commands(cli):
    listing = cli("rules").stdout.decode()
    assert "LIS202  out-of-range" in listing
    doc = cli("rule", "lis104").stdout.decode()
    assert doc.startswith("LIS104 index-out-of-bounds")
    assert "Use instead" in doc and "getriebe[5].vb_refmax" in doc
    assert cli("rule", "LIS999").returncode == 2


def test_schema_command_prints_the_model_schema(cli):
    schema = json.loads(cli("schema").stdout)
    assert schema["title"] == "AxisParameters"
    assert {"kopf", "kenngr", "getriebe", "lr_hw", "antr", "unknown"} <= set(schema["properties"])


def test_statistics(cli):
    bad = FIXTURES / "rules" / "LIS205" / "bad.lis"
    out = cli("lint", str(bad), "--format", "concise", "--statistics").stdout.decode()
    assert "     5  LIS205  bad-reference" in out


def test_cycle_time_and_tolerance_options_drive_lis403(cli):
    bad = str(FIXTURES / "rules" / "LIS403" / "bad.lis")  # vb_reflow 100000 µm/s
    run = lambda *extra: cli("lint", bad, "--format", "concise", "--select", "LIS403", *extra).stdout.decode()  # noqa: E731
    assert ": LIS403 [warning]" in run()
    assert run("--repeatability-tolerance-um", "150") == "All checks passed!\n"
    assert "about 200 µm" in run("--repeatability-tolerance-um", "150", "--cycle-time-us", "2000")

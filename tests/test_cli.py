"""The real entry point (`python -m achslint`), real files on disk, exit codes: version and bare command,
colour, option and configuration mistakes, files that cannot be written, the crash guard."""

from __future__ import annotations

import json
from collections.abc import Callable
from pathlib import Path
from subprocess import CompletedProcess

import pytest

from achslint import __version__

from .conftest import FIXTURES

Cli = Callable[..., CompletedProcess]
X_AXIS = str(FIXTURES / "lists" / "achsmds1.lis")
BROKEN_CONFIG = "select = [\n"


def err(result: CompletedProcess) -> str:
    return result.stderr.decode()


def out(result: CompletedProcess) -> str:
    return result.stdout.decode()


def bad_list(folder: Path) -> Path:
    path = folder / "achsmds1.lis"
    path.write_text("kopf.achs_nr  1\nkenngr.ref_richt  7\nEnd\n", encoding="latin-1")
    return path


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
    assert first["fix"]["applicability"] == "unsafe"  # the rename lets the value take effect: --fix leaves it
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


def test_version_and_bare_command(cli: Cli) -> None:
    version = cli("--version")
    assert version.returncode == 0 and out(version) == f"achslint {__version__}\n"
    bare = cli()
    assert bare.returncode == 2
    assert "Usage: achslint [OPTIONS] COMMAND [ARGS]..." in out(bare)  # the help is the answer


def test_force_color_colours_the_report(cli: Cli, tmp_path: Path) -> None:
    path = bad_list(tmp_path)
    coloured = cli("lint", str(path), "--format", "full", env={"NO_COLOR": None, "FORCE_COLOR": "1"})
    plain = cli("lint", str(path), "--format", "full")
    assert coloured.returncode == plain.returncode == 1
    assert "\x1b[" in out(coloured) and "\x1b[" not in out(plain)


def test_unsafe_fixes_need_fix_or_diff(cli: Cli, tmp_path: Path) -> None:
    result = cli("lint", str(bad_list(tmp_path)), "--unsafe-fixes")
    assert result.returncode == 2
    assert "--unsafe-fixes goes with --fix or --diff" in err(result)


def test_quiet_fix_says_nothing_about_the_count(cli: Cli, tmp_path: Path) -> None:
    path = bad_list(tmp_path)
    result = cli("lint", str(path), "--fix", "--quiet")
    assert result.returncode == 1  # the wrong type is not fixable
    assert "fixed" not in err(result)
    assert path.read_text(encoding="latin-1").endswith("Ende\n")


def test_an_output_file_that_cannot_be_written_is_exit_2(cli: Cli, tmp_path: Path) -> None:
    target = tmp_path / "missing" / "report.txt"
    result = cli("lint", str(bad_list(tmp_path)), "--output-file", str(target))
    assert result.returncode == 2
    assert f"cannot write {target}: no such file or directory" in err(result)


def test_a_broken_configuration_in_the_working_directory_stops_the_report(
    cli: Cli, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    lists, here = tmp_path / "lists", tmp_path / "here"
    lists.mkdir(), here.mkdir()
    (here / ".achslint.toml").write_text(BROKEN_CONFIG, encoding="utf-8")
    monkeypatch.chdir(here)
    result = cli("lint", str(bad_list(lists)))  # the docs URL is a setting of the working directory
    assert result.returncode == 2
    assert ".achslint.toml" in err(result) and "Traceback" not in err(result)


def test_fmt_and_config_with_a_broken_configuration_are_exit_2(cli: Cli, tmp_path: Path) -> None:
    (tmp_path / ".achslint.toml").write_text(BROKEN_CONFIG, encoding="utf-8")
    path = bad_list(tmp_path)
    for args in (("fmt", str(path)), ("config", "--show", str(path))):
        result = cli(*args)
        assert result.returncode == 2, args
        assert str(tmp_path / ".achslint.toml") in err(result), args
    nothing = cli("config", str(path))
    assert nothing.returncode == 2
    assert "nothing to do; use `achslint config --show [PATH]`" in err(nothing)


def test_an_internal_error_is_one_line_unless_debugging(cli: Cli, monkeypatch: pytest.MonkeyPatch) -> None:
    def broken(*args: object, **kwargs: object) -> None:
        raise RuntimeError("something unexpected")

    monkeypatch.setattr("achslint.linting.run.run_lint", broken)  # where `lint` takes it from
    result = cli("lint", X_AXIS)
    assert result.returncode == 2
    assert err(result) == (
        "achslint: internal error: RuntimeError: something unexpected (run with --debug for details)\n"
    )
    with pytest.raises(RuntimeError, match="something unexpected"):
        cli("lint", X_AXIS, "--debug")


def test_help_texts_keep_their_square_brackets(cli):
    """Found by review: rich read `[axes.NAME]` in `report --help` as a style tag and dropped it, so the help
    said "per axis () for a machine"."""
    done = cli("report", "--help", env={"COLUMNS": "200"})
    assert "per axis ([axes.NAME]) for a machine" in done.stdout.decode()

"""What ruff users expect from the command line."""

from __future__ import annotations

import shutil
import subprocess

import pytest

from .conftest import FIXTURES

LISTS = FIXTURES / "lists"  # info findings only, two of them fixable (LIS102 old names)
FIXABLE = FIXTURES / "rules" / "LIS102" / "bad.lis"


def out(result) -> str:
    return result.stdout.decode()


def test_quiet_prints_diagnostics_without_summary_and_silent_prints_nothing(cli):
    quiet = cli("lint", str(LISTS), "-q", "--format", "concise")
    assert "LIS102" in out(quiet) and "fixable" not in out(quiet)
    silent = cli("lint", str(FIXTURES / "rules" / "LIS202" / "bad.lis"), "-s")
    assert silent.returncode == 1 and silent.stdout == b"" and silent.stderr == b""


def test_diff_alone_implies_fix_mode_and_writes_nothing(cli, tmp_path):
    target = tmp_path / "achsmds1.lis"
    target.write_bytes(FIXABLE.read_bytes())
    result = cli("lint", str(target), "--diff")
    assert result.returncode in (0, 1) and "+++" in out(result)
    assert "--fix" not in result.stderr.decode() or "would fix" in result.stderr.decode()
    assert target.read_bytes() == FIXABLE.read_bytes()


def test_statistics_prints_only_the_table(cli):
    text = out(cli("lint", str(LISTS), "--statistics", "--format", "concise"))
    assert text.splitlines() and all(line.split()[1].startswith("LIS") for line in text.splitlines())
    assert ".lis:" not in text


def test_clean_run_says_all_checks_passed_and_fixable_counts(cli):
    clean = cli("lint", str(LISTS), "--select", "LIS5", "--format", "concise")
    assert out(clean).strip() == "All checks passed!"
    assert out(cli("lint", str(LISTS), "--select", "LIS5", "--format", "json")).startswith(
        "{"
    )  # not in machine formats
    fixable = out(cli("lint", str(LISTS), "--format", "concise"))
    assert fixable.rstrip().endswith("2 fixable with --fix")


def test_output_file_is_utf8(cli, tmp_path):
    target = tmp_path / "report.txt"
    result = cli("lint", str(LISTS), "--format", "concise", "--output-file", str(target))
    assert result.stdout == b""
    assert "µ" in target.read_text(encoding="utf-8") or "LIS102" in target.read_text(encoding="utf-8")


def test_include_repeated_and_comma_separated(cli):
    one = out(
        cli(
            "lint",
            str(LISTS),
            "--include",
            "achsmds1*",
            "--include",
            "achsmds2*,achsmds4*",
            "--format",
            "concise",
            "--statistics",
        )
    )
    every = out(cli("lint", str(LISTS), "--format", "concise", "--statistics"))
    assert one == every


def test_extend_exclude_and_force_exclude(cli, tmp_path):
    for name in ("achsmds1.lis", "achsmds2.lis"):
        (tmp_path / name).write_bytes((LISTS / name).read_bytes())
    result = cli("lint", str(tmp_path), "--extend-exclude", "achsmds2*", "--format", "concise")
    assert "achsmds2" not in out(result)
    named = cli(
        "lint", str(tmp_path / "achsmds2.lis"), "--extend-exclude", "achsmds2*", "--format", "concise"
    )
    assert "achsmds2" in out(named)  # a named file is linted unless --force-exclude
    forced = cli("lint", str(tmp_path / "achsmds2.lis"), "--extend-exclude", "achsmds2*", "--force-exclude")
    assert forced.returncode == 2 and "no axis list found" in forced.stderr.decode()


@pytest.mark.skipif(shutil.which("git") is None, reason="git is not installed")
def test_gitignore_is_respected_unless_told(cli, tmp_path):
    subprocess.run(["git", "init", "-q"], cwd=tmp_path, check=True)
    (tmp_path / "old").mkdir()
    (tmp_path / "old" / "achsmds2.lis").write_bytes((LISTS / "achsmds2.lis").read_bytes())
    (tmp_path / "achsmds1.lis").write_bytes((LISTS / "achsmds1.lis").read_bytes())
    (tmp_path / ".gitignore").write_text("old/\n")
    assert "achsmds2" not in out(cli("lint", str(tmp_path), "--format", "concise"))
    assert "achsmds2" in out(cli("lint", str(tmp_path), "--format", "concise", "--no-respect-gitignore"))


def test_one_cycle_time_unit_across_commands(cli, tmp_path):
    bad = FIXTURES / "rules" / "LIS403" / "bad.lis"
    in_ms = out(cli("lint", str(bad), "--cycle-time-ms", "4", "--format", "json", "--select", "LIS403"))
    in_us = out(cli("lint", str(bad), "--cycle-time-us", "4000", "--format", "json", "--select", "LIS403"))
    assert in_ms == in_us and "LIS403" in in_ms
    help_text = out(cli("lint", "--help"))
    assert "--cycle-time-ms" in help_text and "--cycle-time-us" not in help_text


def test_metavars_and_completion(cli):
    help_text = out(cli("lint", "--help", env={"COLUMNS": "200"}))
    for metavar in ("CODES", "PATTERN", "FILE", "DIR", "URL", "MS"):
        assert metavar in help_text, metavar
    assert "--install-completion" in out(cli("--help", env={"COLUMNS": "200"}))


def test_binary_file_is_one_line_not_hundreds_of_findings(cli, tmp_path):
    binary = tmp_path / "achsmds1.lis"
    binary.write_bytes(b"\x7fELF\x02\x01\x01\x00" + bytes(range(256)) * 40 + b"\nkopf.achs_nr 1\n")
    result = cli("lint", str(binary), "--format", "concise")
    assert result.returncode == 2 and result.stdout == b""
    assert result.stderr.decode().count("\n") == 1 and "binary file" in result.stderr.decode()

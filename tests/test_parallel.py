"""--jobs: parallel output equals serial output, in input order."""

from __future__ import annotations

from .conftest import FIXTURES


def test_parallel_equals_serial(cli, tmp_path):
    rule_lists = sorted((FIXTURES / "rules").glob("*/bad.lis"))
    for number, source in enumerate(rule_lists * 2):
        (tmp_path / f"achsmds{number:03d}.lis").write_bytes(source.read_bytes())
    serial = cli("lint", str(tmp_path), "--format", "concise", "--jobs", "1")
    parallel = cli("lint", str(tmp_path), "--format", "concise", "--jobs", "2")
    assert serial.returncode == parallel.returncode == 1
    assert serial.stdout == parallel.stdout
    assert serial.stdout.count(b"\n") > 80


def test_github_format_is_chosen_under_github_actions(cli):
    result = cli("lint", str(FIXTURES / "rules" / "LIS202" / "bad.lis"), env={"GITHUB_ACTIONS": "true"})
    assert result.stdout.startswith(b"::error file=")

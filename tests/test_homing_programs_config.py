"""`homing-programs` in the configuration: a lint of the machine also checks its homing programs (LIS6xx)."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

from .conftest import FIXTURES


def machine(tmp_path: Path, config: str | None) -> Path:
    root = tmp_path / "cnc"
    shutil.copytree(FIXTURES / "machines" / "sdk4", root)
    program = root / "rfp.nc"
    # Q is no axis of this machine: LIS602 at line 3 of the program
    program.write_text(
        program.read_text(encoding="latin-1").replace("G74 Z1", "G74 Z1 Q1"), encoding="latin-1"
    )
    if config is not None:
        (root / ".achslint.toml").write_text(config, encoding="utf-8")
    return root


def findings(result) -> list[tuple[str, int, str]]:
    document = json.loads(result.stdout)
    return sorted((Path(d["path"]).name, d["line"], d["code"]) for d in document["diagnostics"])


def test_programs_named_in_the_configuration_are_checked_with_the_machine(cli, tmp_path):
    root = machine(tmp_path, 'homing-programs = ["rfp.nc"]\n')
    result = cli("lint", str(root), "--format", "json")
    assert ("rfp.nc", 3, "LIS602") in findings(result)
    assert result.returncode == 1


def test_without_the_setting_a_program_is_not_looked_at(cli, tmp_path):
    root = machine(tmp_path, None)
    result = cli("lint", str(root), "--format", "json")
    assert all(name != "rfp.nc" for name, _, _ in findings(result))


def test_a_program_named_twice_is_checked_once(cli, tmp_path):
    root = machine(tmp_path, 'homing-programs = ["rfp.nc"]\n')
    result = cli(
        "lint",
        str(root),
        str(root / "rfp.nc"),
        "--machine",
        str(root / "listen" / "hochlauf.lis"),
        "--format",
        "json",
    )
    assert [f for f in findings(result) if f[0] == "rfp.nc"] == [("rfp.nc", 3, "LIS602")]


def test_a_configured_program_that_does_not_exist_is_an_error(cli, tmp_path):
    root = machine(tmp_path, 'homing-programs = ["home_all.nc"]\n')
    result = cli("lint", str(root), "--format", "json")
    assert result.returncode == 2
    assert "homing-programs names home_all.nc" in result.stderr.decode()

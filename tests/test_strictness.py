"""Nothing passes silently: unknown codes, empty runs, broken configuration, fail-on of the nearest config."""

from __future__ import annotations

import json
import os
import subprocess
from pathlib import Path

import pytest

from achslint import lint_text
from achslint.linting.config import ConfigError, discover

from .conftest import FIXTURES, run_cli

INFO_ONLY = FIXTURES / "lists" / "achsmds4.lis"  # only LIS102 (info): an old parameter name


def run_in(cwd: Path, *args: str) -> subprocess.CompletedProcess:
    """The CLI's entry point run in another working directory (in this process: the working directory is
    all that differs between the runs)."""
    before = os.getcwd()
    os.chdir(cwd)
    try:
        return run_cli(*args)
    finally:
        os.chdir(before)


@pytest.mark.parametrize("option", ["--select", "--ignore", "--extend-select"])
@pytest.mark.parametrize(
    "code,hint",
    [("LIS9999", "did you mean"), ("LIS8", "rule families are LIS0"), ("LIS3O2", "did you mean LIS302?")],
)
def test_unknown_codes_on_the_command_line_are_usage_errors(cli, option, code, hint):
    result = cli("lint", str(INFO_ONLY), option, code)
    assert result.returncode == 2
    message = result.stderr.decode()
    assert f"{option}: '{code}' is not a rule code" in message and hint in message
    assert result.stdout == b""


def test_known_codes_and_prefixes_still_work(cli):
    assert cli("lint", str(INFO_ONLY), "--select", "lis1,LIS102", "--ignore", "LIS5").returncode == 0


@pytest.mark.parametrize(
    "text,key",
    [
        ('select = ["LIS9999"]\n', "select"),
        ('ignore = ["LIS8"]\n', "ignore"),
        ('[per-file-ignores]\n"*.lis" = ["LIS77"]\n', "per-file-ignores"),
        ('[severity]\nLIS4 = "error"\n', "severity"),
    ],
)
def test_unknown_codes_in_the_configuration_are_config_errors(cli, tmp_path, text, key):
    (tmp_path / ".achslint.toml").write_text(text)
    axis = tmp_path / "achsmds1.lis"
    axis.write_bytes(INFO_ONLY.read_bytes())
    with pytest.raises(ConfigError, match=key):
        discover(axis)
    result = cli("lint", str(axis))
    assert result.returncode == 2 and "configuration error" in result.stderr.decode()


def test_unknown_code_in_noqa_is_reported_with_the_closest_code():
    text = "kenngr.antr_typ  1   # noqa: LIS3O2\nEnde\n"
    found = [d for d in lint_text(text) if d.code == "LIS009"]
    assert len(found) == 1
    assert "unknown code `LIS3O2`" in found[0].message and "did you mean LIS302?" in found[0].message


def test_unknown_code_in_a_file_level_noqa_is_reported():
    found = [
        d.message
        for d in lint_text("# achslint: noqa: LIS9999\nkenngr.antr_typ 1\nEnde\n")
        if d.code == "LIS009"
    ]
    assert found and "unknown code `LIS9999`" in found[0]


@pytest.mark.parametrize("make", ["empty", "xml-only", "wrong-names"])
def test_no_list_found_is_exit_2_unless_allowed(cli, tmp_path, make):
    if make == "xml-only":
        (tmp_path / "Update").mkdir()
        (tmp_path / "Update" / "tools.xml").write_text("<Tools><Tool>x</Tool></Tools>")
    elif make == "wrong-names":
        (tmp_path / "notes.txt").write_text("kenngr.antr_typ 1\n")
    result = cli("lint", str(tmp_path))
    assert result.returncode == 2
    assert "no axis list found in" in result.stderr.decode() and "--allow-empty" in result.stderr.decode()
    assert cli("lint", str(tmp_path), "--allow-empty").returncode == 0
    assert cli("fmt", "--check", str(tmp_path)).returncode == 2
    assert cli("fmt", "--check", str(tmp_path), "--allow-empty").returncode == 0


@pytest.mark.parametrize(
    "text,where",
    [
        ("[tool.achslint\nselect = 1\n", ":1:15:"),
        ('[tool.achslint]\nselect = ["LIS1"\n', ":3:1:"),
        ("[tool.black]\nline-length = \n", ":2:15:"),
    ],
)
def test_broken_pyproject_is_exit_2_with_file_line_and_column(cli, tmp_path, text, where):
    (tmp_path / "pyproject.toml").write_text(text)
    axis = tmp_path / "achsmds1.lis"
    axis.write_bytes(INFO_ONLY.read_bytes())
    result = cli("lint", str(axis))
    assert result.returncode == 2
    message = result.stderr.decode()
    assert f"{tmp_path / 'pyproject.toml'}{where}" in message and "not valid TOML" in message
    assert message.count("\n") == 1


def test_every_setting_comes_from_the_config_nearest_each_file(tmp_path):
    """The same tree linted from three working directories gives the same findings and exit code."""
    root = tmp_path / "root"
    strict = root / "cfg2"
    strict.mkdir(parents=True)
    (strict / ".achslint.toml").write_text('fail-on = "info"\nignore = ["LIS404"]\n')
    (strict / "achsmds1.lis").write_bytes(INFO_ONLY.read_bytes())
    lenient = root / "plain"
    lenient.mkdir()
    (lenient / "achsmds1.lis").write_bytes(INFO_ONLY.read_bytes())
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    runs = {
        root: run_in(root, "lint", "cfg2", "plain", "--format", "json"),
        strict: run_in(strict, "lint", ".", "../plain", "--format", "json"),
        elsewhere: run_in(elsewhere, "lint", str(strict), str(lenient), "--format", "json"),
    }
    seen = set()
    for where, result in runs.items():
        assert result.returncode == 1, (where, result.stderr.decode())
        found = json.loads(result.stdout)["diagnostics"]
        by_folder = sorted(((where / d["path"]).resolve().parent.name, d["line"], d["code"]) for d in found)
        assert not [item for item in by_folder if item[0] == "cfg2" and item[2] == "LIS404"]  # ignored there
        seen.add(tuple(by_folder))
    assert len(seen) == 1
    # Only the lenient folder: its info findings do not fail, from anywhere.
    assert run_in(root, "lint", "plain").returncode == 0
    assert run_in(strict, "lint", "../plain").returncode == 0

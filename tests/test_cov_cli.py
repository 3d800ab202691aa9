"""Command-line paths the other CLI tests leave out: version, bare `achslint`, colour forced by the
environment, option and configuration mistakes, files that cannot be read or written, the crash guard."""

from __future__ import annotations

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


def test_dry_run_scenarios_that_cannot_be_read(cli: Cli, tmp_path: Path) -> None:
    folder = cli("dry-run", X_AXIS, "--scenario", str(tmp_path))
    assert folder.returncode == 2
    assert err(folder).startswith(f"achslint: cannot read scenario {tmp_path}: ")
    latin = tmp_path / "scenario.toml"
    latin.write_bytes("# Nocken bei -100 µm\ncam = [-120.0, -100.0]\n".encode("latin-1"))
    not_utf8 = cli("dry-run", X_AXIS, "--scenario", str(latin))
    assert not_utf8.returncode == 2
    assert err(not_utf8) == f"achslint: {latin}: scenario is not UTF-8 text (byte 19); save it as UTF-8\n"


def test_dry_run_sweep_as_text(cli: Cli) -> None:
    result = cli("dry-run", X_AXIS, "--sweep", "20", "--cam-jitter", "0.01")
    assert result.returncode == 1  # some starts of the assumed geometry run into a limit switch
    text = out(result)
    assert "NOTE: the sweep runs in an ASSUMED geometry" in text
    assert "Sweep of 20 runs (start between -1010 and 1010 mm): failed ×" in text
    assert "  failed: limit switch reached ×" in text


def test_an_internal_error_is_one_line_unless_debugging(cli: Cli, monkeypatch: pytest.MonkeyPatch) -> None:
    def broken(*args: object, **kwargs: object) -> None:
        raise RuntimeError("something unexpected")

    monkeypatch.setattr("achslint.api.run_lint", broken)
    result = cli("lint", X_AXIS)
    assert result.returncode == 2
    assert err(result) == (
        "achslint: internal error: RuntimeError: something unexpected (run with --debug for details)\n"
    )
    with pytest.raises(RuntimeError, match="something unexpected"):
        cli("lint", X_AXIS, "--debug")


def test_a_folder_given_as_scenario_is_named_as_such(cli, tmp_path):
    result = cli("dry-run", str(FIXTURES / "lists" / "achsmds1.lis"), "--scenario", str(tmp_path))
    assert result.returncode == 2
    assert (
        result.stderr.decode().strip()
        == f"achslint: cannot read scenario {tmp_path}: it is a folder, not a file"
    )

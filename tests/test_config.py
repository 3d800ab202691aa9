"""Configuration discovery, precedence and validation, through the real entry point."""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

from achslint.linting.config import ConfigError, Settings, discover, load_file

BAD_SPEED = b"kenngr.antr_typ 1\nlr_hw[0].cam_direct_access 0\ngetriebe[0].a_ref 500\ngetriebe[0].vb_refmax 20000\ngetriebe[0].vb_reflow 100000\nEnde\n"  # LIS302
UNKNOWN = b"kenngr.ref_ricth 1\nEnde\n"  # LIS101


def codes(result) -> list[str]:
    return [d["code"] for d in json.loads(result.stdout)["diagnostics"]]


def write(path: Path, text: str | bytes) -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_bytes(text if isinstance(text, bytes) else text.encode())
    return path


def test_nearest_config_wins_and_precedence_of_names(tmp_path):
    write(tmp_path / "pyproject.toml", "[tool.achslint]\nignore = ['LIS302']\n")
    write(tmp_path / "machine" / "achslint.toml", "ignore = ['LIS101']\n")
    write(tmp_path / "machine" / ".achslint.toml", "ignore = ['LIS2']\n")
    axis = write(tmp_path / "machine" / "x" / "achsmds1.lis", BAD_SPEED)
    resolved = discover(axis)
    assert resolved.path == tmp_path / "machine" / ".achslint.toml"
    assert resolved.settings.ignore == ["LIS2"]
    other = write(tmp_path / "other" / "achsmds1.lis", BAD_SPEED)
    assert discover(other).path == tmp_path / "pyproject.toml"


def test_pyproject_without_table_is_skipped(tmp_path):
    write(tmp_path / "pyproject.toml", "[tool.black]\nline-length = 100\n")
    axis = write(tmp_path / "achsmds1.lis", BAD_SPEED)
    assert discover(axis).path is None


def test_config_applies_and_cli_overrides(cli, tmp_path):
    write(tmp_path / "achslint.toml", "ignore = ['LIS302']\nunknown-parameters = 'error'\n")
    axis = write(tmp_path / "achsmds1.lis", BAD_SPEED.replace(b"Ende\n", b"") + UNKNOWN)
    result = cli("lint", str(axis), "--format", "json")
    found = json.loads(result.stdout)["diagnostics"]
    assert "LIS302" not in [d["code"] for d in found]
    assert [d["severity"] for d in found if d["code"] == "LIS101"] == ["error"]
    overridden = cli(
        "lint", str(axis), "--format", "json", "--unknown-parameters", "ignore", "--select", "LIS1,LIS3"
    )
    assert "LIS101" not in codes(overridden) and "LIS302" not in codes(
        overridden
    )  # --ignore from config still applies


def test_select_severity_and_fail_on_from_config(cli, tmp_path):
    write(
        tmp_path / "achslint.toml", "select = ['LIS3']\nfail-on = 'warning'\n[severity]\nLIS302 = 'warning'\n"
    )
    axis = write(tmp_path / "achsmds1.lis", BAD_SPEED)
    result = cli("lint", str(axis), "--format", "json", "--config", str(tmp_path / "achslint.toml"))
    found = json.loads(result.stdout)["diagnostics"]
    assert [(d["code"], d["severity"]) for d in found] == [("LIS302", "warning")]
    assert result.returncode == 1  # fail-on warning


def test_per_file_ignores(cli, tmp_path):
    write(tmp_path / "achslint.toml", "[per-file-ignores]\n'legacy/*.lis' = ['LIS302']\n")
    old = write(tmp_path / "legacy" / "achsmds1.lis", BAD_SPEED)
    new = write(tmp_path / "new" / "achsmds1.lis", BAD_SPEED)
    result = cli("lint", str(tmp_path), "--format", "json", "--select", "LIS302")
    paths = [d["path"] for d in json.loads(result.stdout)["diagnostics"]]
    assert paths == [str(new)]
    assert str(old) not in paths


def test_include_and_exclude(cli, tmp_path):
    write(tmp_path / "achslint.toml", "include = ['*.lis']\nexclude = ['archive/*']\n")
    write(tmp_path / "axis_x.lis", BAD_SPEED)
    write(tmp_path / "archive" / "axis_old.lis", BAD_SPEED)
    result = cli("lint", str(tmp_path), "--format", "json", "--select", "LIS302")
    assert [Path(d["path"]).name for d in json.loads(result.stdout)["diagnostics"]] == ["axis_x.lis"]


def test_stdin_filename_finds_config_and_per_file_ignores(cli, tmp_path, monkeypatch):
    write(tmp_path / "achslint.toml", "[per-file-ignores]\n'x/*.lis' = ['LIS302']\n")
    relative = tmp_path / "x" / "achsmds1.lis"
    result = cli(
        "lint",
        "-",
        "--stdin-filename",
        str(relative),
        "--format",
        "json",
        "--select",
        "LIS302",
        stdin=BAD_SPEED,
    )
    assert codes(result) == []
    elsewhere = cli(
        "lint",
        "-",
        "--stdin-filename",
        str(tmp_path / "y" / "achsmds1.lis"),
        "--format",
        "json",
        "--select",
        "LIS302",
        stdin=BAD_SPEED,
    )
    assert codes(elsewhere) == ["LIS302"]


def test_unknown_key_is_exit_2_naming_key_and_file(cli, tmp_path):
    config = write(tmp_path / "achslint.toml", "ignroe = ['LIS302']\n")
    axis = write(tmp_path / "achsmds1.lis", BAD_SPEED)
    result = cli("lint", str(axis))
    assert result.returncode == 2
    message = result.stderr.decode()
    assert str(config) in message and "unknown key `ignroe`" in message
    assert "Traceback" not in message


def test_bad_values_are_config_errors(tmp_path):
    for text, key in (
        ("fail-on = 'sometimes'\n", "fail-on"),
        ("select = ['E501']\n", "select"),
        ("cycle-time-us = -5\n", "cycle-time-us"),
        ("[severity]\nLIS302 = 'fatal'\n", "severity"),
    ):
        path = write(tmp_path / "achslint.toml", text)
        try:
            load_file(path)
        except ConfigError as exc:
            assert key in str(exc) and str(path) in str(exc)
        else:
            raise AssertionError(f"{text!r} was accepted")
    write(tmp_path / "achslint.toml", "select = [\n")
    try:
        load_file(tmp_path / "achslint.toml")
    except ConfigError as exc:
        assert "not valid TOML" in str(exc)


def test_config_show(cli, tmp_path):
    write(tmp_path / "pyproject.toml", "[tool.achslint]\ncycle-time-us = 2000\n")
    result = cli("config", "--show", str(tmp_path))
    out = result.stdout.decode()
    assert f"# configuration: {tmp_path / 'pyproject.toml'}" in out
    assert json.loads(out.split("\n", 1)[1])["cycle-time-us"] == 2000


def test_defaults_match_the_spec():
    settings = Settings()
    assert (settings.fail_on, settings.unknown_parameters, settings.cycle_time_us) == ("error", "warn", 1000)
    assert settings.include == ["achsmds*.lis"]


def test_overrides_name_only_settings_and_survive_a_trip_to_a_worker_process():
    import pickle

    import pytest

    from achslint.linting.config import Overrides, Settings

    given = Overrides(ignore=["LIS101"], extend_exclude=["old/*"], fail_on="warning")
    assert given.fail_on == "warning" and given.select is None
    with pytest.raises(AttributeError):
        given.fail_onn  # noqa: B018  (a misspelt setting is an error, not None)
    with pytest.raises(TypeError):
        Overrides(fail_onn="info")
    copy = pickle.loads(pickle.dumps(given))
    assert copy.key() == given.key()
    applied = copy.apply(Settings(ignore=["LIS9"], exclude=["tmp/*"]))
    assert applied.ignore == ["LIS9", "LIS101"] and applied.exclude == ["tmp/*", "old/*"]
    assert applied.fail_on == "warning"


def test_the_cycle_time_is_written_in_ms_as_everywhere_else(tmp_path: Path) -> None:
    # --cycle-time-ms, the scenario's cycle_time_ms and the configuration's cycle-time-ms: one unit
    (tmp_path / "achsmds1.lis").write_text("kopf.achs_nr 1\nEnde\n")
    config = tmp_path / ".achslint.toml"
    config.write_text("cycle-time-ms = 0.25\n")
    assert load_file(config).settings.cycle_time_us == 250
    config.write_text("cycle-time-us = 2000\n")  # the older spelling still reads
    assert load_file(config).settings.cycle_time_us == 2000
    for text, said in (
        ("cycle-time-ms = 500\n", "key `cycle-time-ms`: 500 is not a cycle time in ms from 0.05 to 100"),
        ('cycle-time-ms = "1"\n', "key `cycle-time-ms`: '1' is not a cycle time in ms"),
        ("cycle-time-ms = 1\ncycle-time-us = 1000\n", "keys `cycle-time-ms` and `cycle-time-us` both"),
    ):
        config.write_text(text)
        with pytest.raises(ConfigError, match=re.escape(said)):
            load_file(config)

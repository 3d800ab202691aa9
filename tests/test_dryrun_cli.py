"""`achslint dry-run` through the real entry point."""

from __future__ import annotations

import json

from .conftest import FIXTURES

X_AXIS = str(FIXTURES / "lists" / "achsmds1.lis")


def test_default_scenario_is_printed_as_assumed(cli):
    result = cli("dry-run", X_AXIS)
    out = result.stdout.decode()
    assert result.returncode == 0, result.stderr
    assert "Assumed (not given): start_position, cam" in out
    assert "Outcome: homed" in out
    assert "Final position: -950.1 mm (homed, at standstill)" in out


def test_scenario_file_and_options(cli, tmp_path):
    scenario = tmp_path / "scenario.toml"
    scenario.write_text(
        "start_position = 50.0\ncam = [-300.0, -250.0]\nzero_pulse_period = 4.0\n"
        "zero_pulse_phase = -251.0\nhardware_latch = true\nlimit_switches = [-400.0, 400.0]\n"
    )
    document = json.loads(cli("dry-run", X_AXIS, "--scenario", str(scenario), "--format", "json").stdout)
    assert document["outcome"] == "homed"
    assert document["reference"]["position"] == -251.0
    # Three-phase homing on the cam reads no fixed stop: it is not assumed (issue 26 item 12).
    assert set(document["scenario"]["assumed"]) == {"cam_jitter", "cycle_time_ms"}
    moved = json.loads(
        cli(
            "dry-run", X_AXIS, "--scenario", str(scenario), "--format", "json", "--zero-pulse-phase", "-253.0"
        ).stdout
    )
    assert moved["reference"]["position"] == -253.0


def test_missed_cam_is_exit_1_with_reason(cli):
    result = cli(
        "dry-run",
        X_AXIS,
        "--start",
        "-150",
        "--cam",
        "-120,-100",
        "--limit-switches",
        "-200,200",
        "--format",
        "json",
    )
    document = json.loads(result.stdout)
    assert result.returncode == 1
    assert document["outcome"] == "failed" and "limit switch" in document["failure"]


def test_bad_scenario_is_exit_2(cli, tmp_path):
    scenario = tmp_path / "s.toml"
    scenario.write_text("cam = [5.0, -5.0]\nspeed = 3\n")
    result = cli("dry-run", X_AXIS, "--scenario", str(scenario))
    assert result.returncode == 2
    message = result.stderr.decode()
    assert "unknown key `speed`" in message and "Traceback" not in message
    assert cli("dry-run", X_AXIS, "--cam", "1").returncode == 2


def test_sweep_in_json(cli):
    document = json.loads(
        cli("dry-run", X_AXIS, "--sweep", "200", "--cam-jitter", "0.01", "--format", "json").stdout
    )
    assert document["sweep"]["runs"] == 200
    assert sum(document["sweep"]["outcomes"].values()) == 200


def test_plot_other_than_png_or_svg_is_refused(cli, tmp_path):
    # The PNG and SVG plots themselves: test_dryrun_fidelity.test_plot_png_has_size_and_is_not_blank.
    refused = cli("dry-run", X_AXIS, "--plot", str(tmp_path / "homing.gif"))
    assert refused.returncode == 2 and "--plot needs a .png or .svg file name" in refused.stderr.decode()
    assert not (tmp_path / "homing.gif").exists()


def test_dry_run_scenarios_that_cannot_be_read(cli, tmp_path):
    folder = cli("dry-run", X_AXIS, "--scenario", str(tmp_path))
    assert folder.returncode == 2
    assert (
        folder.stderr.decode() == f"achslint: cannot read scenario {tmp_path}: it is a folder, not a file\n"
    )
    latin = tmp_path / "scenario.toml"
    latin.write_bytes("# Nocken bei -100 µm\ncam = [-120.0, -100.0]\n".encode("latin-1"))
    not_utf8 = cli("dry-run", X_AXIS, "--scenario", str(latin))
    assert not_utf8.returncode == 2
    assert (
        not_utf8.stderr.decode()
        == f"achslint: {latin}: scenario is not UTF-8 text (byte 19); save it as UTF-8\n"
    )


def test_dry_run_sweep_as_text(cli):
    result = cli("dry-run", X_AXIS, "--sweep", "20", "--cam-jitter", "0.01")
    assert result.returncode == 1  # some starts of the assumed geometry run into a limit switch
    text = result.stdout.decode()
    assert "NOTE: the sweep runs in an ASSUMED geometry" in text
    assert "Sweep of 20 runs (start between -1010 and 1010 mm): failed ×" in text
    assert "  failed: limit switch reached ×" in text

"""`achslint dry-run hochlauf.lis --program rfp.nc`: the machine dry-run through the real entry point."""

from __future__ import annotations

import json
import re
import shutil
from pathlib import Path

import pytest

from .conftest import FIXTURES, ROOT

EXAMPLE = ROOT / "docs" / "dry-run" / "machine"
STARTUP = str(EXAMPLE / "listen" / "hochlauf.lis")
PROGRAM = str(EXAMPLE / "rfp.nc")
SCENARIO = str(EXAMPLE / "machine.toml")
PORTAL = FIXTURES / "machines" / "portal"


def machine(cli, *args: str):
    return cli("dry-run", STARTUP, "--program", PROGRAM, "--scenario", SCENARIO, *args)


def test_readme_example_text_summary(cli):
    result = machine(cli)
    out = result.stdout.decode()
    assert result.returncode == 0, result.stderr
    # Z homes upwards in 4.628 s and moves 54.53 mm down at 500 mm/min (6.552 s); X/Y, then A with B
    # standing still, then the spindle.
    assert re.search(r"N15 G01 G90 Z200 F500\s+4\s+Z\s+4\.628\s+11\.180\s+done", out)
    assert re.search(r"2\s+A B \(still\)\s+16\.680\s+23\.919\s+done", out)
    assert "Total time 29.21 s" in out
    assert "B stands still (homing type IGNORE_ABS_POS) while the other axes of its group move" in out
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    assert "Total time 29.21 s" in readme  # the README shows this run


def test_json_is_versioned_and_complete(cli):
    result = machine(cli, "--format", "json")
    document = json.loads(result.stdout)
    assert result.returncode == 0
    assert (document["version"], document["kind"]) == (1, "machine dry-run")
    assert [b["text"] for b in document["blocks"]] == [
        "N10 G74 Z1",
        "N15 G01 G90 Z200 F500",
        "N20 G74 X1 Y1 A2 B2 S3",
    ]
    groups = document["blocks"][2]["groups"]
    assert [(g["sequence"], g["axes"], g["still"]) for g in groups] == [
        (1, ["X", "Y"], []),
        (2, ["A", "B"], ["B"]),
        (3, ["S"], []),
    ]
    axes = {a["name"]: a for a in document["axes"]}
    assert {n: a["outcome"] for n, a in axes.items()} == {
        "X": "homed",
        "Y": "homed",
        "Z": "homed",
        "A": "homed",
        "B": "skipped",
        "S": "homed",
    }
    assert axes["Z"]["final_position"] == 200.0 and axes["S"]["unit"] == "deg" and axes["S"]["ends_moving"]
    assert document["total_time"] == pytest.approx(29.21033, abs=1e-5)
    assert document["failure"] is None and document["outcome"] == "done"
    assert "NaN" not in result.stdout.decode()


def test_sweep_over_the_machine(cli):
    result = machine(cli, "--sweep", "40", "--format", "json")
    summary = json.loads(result.stdout)["sweep"]
    assert summary["runs"] == 40 and summary["completed"] + summary["failed"] == 40
    assert summary["start_ranges"]["X"] == [-30.0, 810.0]
    if summary["failed"]:
        assert result.returncode == 1
        assert sum(entry["failed"] for entry in summary["failures"]) == summary["failed"]
    else:
        assert result.returncode == 0
    allowed = machine(cli, "--sweep", "40", "--allow-failures")
    assert allowed.returncode == 0 and "Sweep of 40 runs" in allowed.stdout.decode()


def test_gantry_and_drive_controlled_spindle_of_the_portal(cli):
    result = cli(
        "dry-run",
        str(PORTAL / "listen" / "hochlauf.lis"),
        "--program",
        str(PORTAL / "rfp.nc"),
        "--format",
        "json",
    )
    document = json.loads(result.stdout)
    axes = {a["name"]: a for a in document["axes"]}
    assert axes["Y2"]["gantry"] == {"role": "slave", "partner": "Y"}
    assert {p["kind"] for p in axes["Y2"]["phases"]} == {"following"}
    assert [p["start_time"] for p in axes["Y2"]["phases"]] == [p["start_time"] for p in axes["Y"]["phases"]]
    assert axes["S"]["outcome"] == "not_simulated"


def test_explain_of_the_portal_names_each_homing_type_once(cli):
    out = cli("explain", str(PORTAL / "listen" / "hochlauf.lis"), "--color", "never").stdout.decode()
    assert "homing skipped (IGNORE_ABS_POS)" in out and "(IGNORE_ABS_POS) (IGNORE_ABS_POS)" not in out
    assert "homing disabled (DISABLED)" in out


def portal_copy(tmp_path: Path, program: str, scenario: str) -> tuple[str, str, str]:
    """The portal in tmp_path with Y2's reference position 1 mm above Y's (-1449 mm against -1450 mm), a
    program and a machine scenario: start-up list, program, scenario."""
    folder = tmp_path / "portal"
    shutil.copytree(PORTAL, folder)
    slave = folder / "listen" / "achsmds7.lis"
    text = slave.read_text(encoding="latin-1")
    assert "getriebe[0].pos_refpkt                    -14500000" in text
    slave.write_text(text.replace("-14500000", "-14490000"), encoding="latin-1")
    (folder / "p.nc").write_text(program, encoding="utf-8")
    (folder / "machine.toml").write_text(scenario, encoding="utf-8")
    return str(folder / "listen" / "hochlauf.lis"), str(folder / "p.nc"), str(folder / "machine.toml")


def test_the_portal_s_gantry_slave_outside_the_channel_moves_and_homes_with_its_master(cli, tmp_path):
    # Y2 is in no channel; it stands 3 mm ahead of Y and makes every move of Y: the homing and the 10 mm
    # after it. It takes its own reference position (-1449 mm) when Y takes its own (-1450 mm).
    startup, program, scenario = portal_copy(
        tmp_path,
        "N10 G74 Y1\nN20 G01 G91 Y10 F1000\nN30 M30\n",
        "[axes.Y]\nstart_position = 0.0\n[axes.Y2]\nstart_position = 3.0\n",
    )
    result = cli("dry-run", startup, "--program", program, "--scenario", scenario, "--format", "json")
    assert result.returncode == 0, result.stderr
    document = json.loads(result.stdout)
    axes = {a["name"]: a for a in document["axes"]}
    y, y2 = axes["Y"], axes["Y2"]
    assert (y2["logical_number"], y2["gantry"], y2["outcome"]) == (
        7,
        {"role": "slave", "partner": "Y"},
        "homed",
    )
    assert y["gantry"] == {"role": "master", "partner": "Y2"}
    assert [p["kind"] for p in y2["phases"]] == ["following"] * len(y["phases"])
    assert [p["kind"] for p in y["phases"]][-1] == "move"  # the G01 after the homing
    for master, slave in zip(y["phases"], y2["phases"], strict=True):
        assert (slave["start_time"], slave["end_time"]) == (master["start_time"], master["end_time"])
        assert slave["start_position"] == pytest.approx(master["start_position"] + 3.0)
        assert slave["end_position"] == pytest.approx(master["end_position"] + 3.0)
    assert y2["position"] == pytest.approx(y["position"] + 3.0)
    # both referenced at the same moment, each to its own reference position
    assert y2["reference"]["time"] == y["reference"]["time"]
    assert y2["reference"]["position"] == pytest.approx(y["reference"]["position"] + 3.0)
    assert (y["reference"]["value"], y2["reference"]["value"]) == (-1450.0, -1449.0)
    assert y2["final_position"] == pytest.approx(y["final_position"] + 1.0)
    assert y["final_position"] == pytest.approx(y["reference"]["value"] + 10.0, abs=0.2)  # braking + 10 mm
    groups = document["blocks"][0]["groups"]
    assert [(g["axes"], g["following"]) for g in groups] == [(["Y"], ["Y2"])]


def test_a_slave_outside_the_channel_with_a_homing_of_its_own_homes_after_its_master(cli, tmp_path):
    # Without gantry_slave_no_homing Y2 follows Y's homing, then runs its own while Y follows it, though
    # the program names Y alone; it is homed, with no note that its homing "still has to run".
    startup, program, scenario = portal_copy(tmp_path, "N10 G74 Y1\nN20 M30\n", "")
    slave = Path(startup).parent / "achsmds7.lis"
    text = slave.read_text(encoding="latin-1")
    slave.write_text(text.replace("gantry_slave_no_homing             1", "gantry_slave_no_homing 0"))
    result = cli("dry-run", startup, "--program", program, "--scenario", scenario, "--format", "json")
    assert result.returncode == 0, result.stderr
    axes = {a["name"]: a for a in json.loads(result.stdout)["axes"]}
    y, y2 = axes["Y"], axes["Y2"]
    own = [p for p in y2["phases"] if p["kind"] == "homing"]
    assert own and [p["kind"] for p in y2["phases"]] == ["following"] * (len(y2["phases"]) - len(own)) + [
        "homing"
    ] * len(own)
    master_done = [p for p in y["phases"] if p["kind"] == "homing"][-1]["end_time"]
    assert own[0]["start_time"] == master_done  # its own homing starts when the master's has ended
    assert [p["kind"] for p in y["phases"]][-len(own) :] == ["following"] * len(own)
    assert (y2["outcome"], y2["reference"]["value"]) == ("homed", -1449.0)
    assert y2["warnings"] == []


def test_a_program_naming_the_gantry_slave_outside_the_channel_stops_there(cli, tmp_path):
    startup, program, scenario = portal_copy(tmp_path, "N10 G74 Y2=1\nN20 G74 Y1\nN30 M30\n", "")
    result = cli("dry-run", startup, "--program", program, "--scenario", scenario, "--format", "json")
    assert result.returncode == 1, result.stderr
    failure = json.loads(result.stdout)["failure"]
    assert (failure["axis"], failure["line"], failure["cause"]) == (
        "Y2",
        1,
        "gantry slave named in the program",
    )
    assert "G74 names Y2, the gantry slave of Y: it is no axis of the channel" in failure["reason"]
    assert failure["reason"].endswith("moves only with its master; program Y")


def test_disabled_axis_fails_with_exit_1(cli, tmp_path):
    program = tmp_path / "rfp.nc"
    program.write_text("%RFP.NC\nN10 G74 Z1\nN20 G74 X1 C2\nN30 G74 A1\nM30\n")
    result = cli(
        "dry-run", str(PORTAL / "listen" / "hochlauf.lis"), "--program", str(program), "--format", "json"
    )
    document = json.loads(result.stdout)
    assert result.returncode == 1
    failure = document["failure"]
    assert (failure["axis"], failure["code"], failure["line"]) == ("C", "P-ERR-50686", 3)
    assert [b["outcome"] for b in document["blocks"]] == ["done", "failed", "not_run"]
    assert {a["name"]: a["outcome"] for a in document["axes"]}["A"] == "not_run"
    text = cli("dry-run", str(PORTAL / "listen" / "hochlauf.lis"), "--program", str(program))
    assert "FAILED at" in text.stdout.decode() and "P-ERR-50686" in text.stdout.decode()


@pytest.mark.parametrize(
    ("scenario", "expected"),
    [
        ("[axes.Q]\nstart_position = 1.0\n", r"machine.toml: \[axes.Q\]: the machine has no axis Q"),
        ("[axes.x1]\nstart_position = 1.0\n", r"did you mean \[axes.X\]"),
        ("[axes.X]\nspeed = 3\n", r"machine.toml: \[axes.X\]: unknown key `speed` \(known: start_position"),
        ("[axes.X]\ncam = [5.0, nan]\n", r"\[axes.X\]: `cam.1`"),
        ("speed = 1\n", r"machine.toml: unknown key `speed`"),
        ("axes = 3\n", r"`axes` holds one table per axis name"),
        ("[axes.X\n", r"machine.toml:1:\d+: machine scenario is not valid TOML"),
    ],
)
def test_bad_machine_scenario_is_exit_2(cli, tmp_path, scenario, expected):
    path = tmp_path / "machine.toml"
    path.write_text(scenario)
    result = cli("dry-run", STARTUP, "--program", PROGRAM, "--scenario", str(path))
    message = result.stderr.decode()
    assert result.returncode == 2, message
    assert re.search(expected, message) and "Traceback" not in message


def test_refusals_are_exit_2(cli, tmp_path):
    broken = tmp_path / "rfp.nc"
    broken.write_text("N10 G74 Z[P1\n")  # a `[` never closed
    result = cli("dry-run", STARTUP, "--program", str(broken))
    assert result.returncode == 2 and "rfp.nc:1:" in result.stderr.decode()
    missing = cli("dry-run", STARTUP, "--program", str(tmp_path / "none.nc"))
    assert missing.returncode == 2 and "cannot read the homing program" in missing.stderr.decode()
    axis_list = cli("dry-run", str(FIXTURES / "lists" / "achsmds1.lis"), "--program", PROGRAM)
    assert axis_list.returncode == 2 and "names no axis lists" in axis_list.stderr.decode()
    channel = cli("dry-run", STARTUP, "--program", PROGRAM, "--channel", "2")
    assert channel.returncode == 2 and "no channel 2" in channel.stderr.decode()
    single = cli("dry-run", STARTUP, "--program", PROGRAM, "--cam", "1,2")
    assert single.returncode == 2 and "[axes.NAME]" in single.stderr.decode()


def test_timeline_plot(cli, tmp_path):
    png = tmp_path / "machine.png"
    result = machine(cli, "--plot", str(png))
    assert result.returncode == 0 and png.read_bytes().startswith(b"\x89PNG")
    assert f"wrote {png}" in result.stderr.decode()
    assert machine(cli, "--plot", str(tmp_path / "machine.txt")).returncode == 2


def test_timeline_figure_marks_lanes_groups_and_failure(tmp_path):
    pytest.importorskip("matplotlib")
    import matplotlib.pyplot as plt

    from achslint.machine.run import machine_dry_run
    from achslint.output.figures import build_machine_figure

    program = tmp_path / "rfp.nc"
    program.write_text("N10 G74 Z1\nN20 G74 X1 Y1\n")
    scenario = tmp_path / "machine.toml"
    scenario.write_text(
        (EXAMPLE / "machine.toml").read_text(encoding="utf-8").replace("[-30.0, 610.0]", "[-3.0, 610.0]")
    )
    run, _ = machine_dry_run(
        EXAMPLE / "listen" / "hochlauf.lis", program, scenario
    )  # Y's limit switch -3 lies before its zero pulse -4.5
    assert run.failure is not None and run.failure.axis == "Y"
    figure = build_machine_figure(run)
    try:
        timeline = figure.axes[0]
        labels = [t.get_text() for t in timeline.get_yticklabels()]
        assert labels[0].startswith("S") and labels[-1] == "X (aborted)"  # one lane per axis, X on top
        assert any(line.get_gid() == "failure" for line in timeline.lines)
        assert len(figure.axes) == 1 + 3  # the timeline, then X, Y and Z, the axes that moved
    finally:
        plt.close(figure)


def test_a_program_of_more_blocks_than_the_dry_run_runs_is_refused_at_once(cli, tmp_path):
    """Found by review: a 1.3 MB program of 100,000 `G74 X1` blocks (far below the 16 MB a program may have)
    ran for over a minute and took 1.2 GB, as each block keeps its motion. Above 2,000 homing and motion
    blocks the run is refused in one line naming the program; comment lines do not count."""
    from achslint.machine.run import MAX_PROGRAM_MOVES

    program = tmp_path / "rfp.nc"
    blocks = "".join(f"N{i} G74 X1\n" for i in range(MAX_PROGRAM_MOVES + 1))
    program.write_text(blocks + "M30\n")
    done = cli("dry-run", str(PORTAL / "listen" / "hochlauf.lis"), "--program", str(program))
    assert done.returncode == 2
    message = done.stderr.decode()
    assert (
        str(program) in message and "2,001 homing and motion blocks" in message and "at most 2,000" in message
    )
    assert done.stdout == b""
    # the largest program it runs, with comment lines between the blocks, is run
    program.write_text("".join(f"; step {i}\nN{i} G74 X1\n" for i in range(MAX_PROGRAM_MOVES)) + "M30\n")
    done = cli(
        "dry-run", str(PORTAL / "listen" / "hochlauf.lis"), "--program", str(program), "--format", "json"
    )
    assert done.returncode in (0, 1), done.stderr
    assert len(json.loads(done.stdout)["blocks"]) >= MAX_PROGRAM_MOVES

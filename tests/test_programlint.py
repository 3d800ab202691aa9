"""Homing programs against a machine: LIS6xx through the library, `lint --machine` and `explain`."""

from __future__ import annotations

import json
import shutil

import pytest

from achslint.axis.resolved import resolve_bytes
from achslint.homing import classify
from achslint.linting.program import check_program
from achslint.machine.build import build_machine
from achslint.machine.model import ChannelView, MachineAxis
from achslint.machine.program import read_program

from .conftest import FIXTURES, run_cli
from .conftest import PORTAL_STARTUP as PORTAL

SDK4 = FIXTURES / "machines" / "sdk4" / "listen" / "hochlauf.lis"


def cli(*args: str):
    """The CLI in process, with its output as text."""
    result = run_cli(*args)
    result.stdout, result.stderr = result.stdout.decode(), result.stderr.decode()
    return result


def findings(machine, text: str) -> list[tuple[int, int, str]]:
    return [(d.line, d.column, d.code) for d in check_program(read_program(text.encode(), "p.nc"), machine)]


def test_the_portals_own_program_is_clean(portal):
    assert findings(portal, (FIXTURES / "machines" / "portal" / "rfp.nc").read_text()) == []


def test_one_finding_of_each_kind_at_its_word(portal):
    text = (
        "N5 G01 G90 Z200 F500\n"  # Z moves before it is homed: LIS606 at Z200 (column 12)
        "N10 G74 Z1 Q1 Z2\n"  # Q is no axis (LIS602, column 12); Z twice (LIS603, column 15)
        "N20 G74 X1 B1 C2\n"  # B stands while X moves (LIS607, column 12); C is DISABLED (LIS604, column 15)
        "N30 G74 Y2=1 Y2\n"  # the gantry slave is no channel axis (LIS602 alone, not LIS605, column 9)
        "N40 G74 A0\n"  # order 0 (LIS601, column 9)
    )
    assert findings(portal, text) == [
        (1, 12, "LIS606"),
        (2, 12, "LIS602"),
        (2, 15, "LIS603"),
        (3, 12, "LIS607"),
        (3, 15, "LIS604"),
        (4, 9, "LIS602"),
        (5, 9, "LIS601"),
    ]


def test_the_portals_gantry_slave_is_no_axis_of_its_channel(portal):
    # Y2 follows Y (kenngr.gantry_ax_nr 2) and the channel names only Y: a program naming Y2 gets one
    # finding, LIS602 telling to program the master, never LIS605 or LIS606 about an axis it cannot name.
    found = check_program(read_program(b"N10 G74 Y2=1\nN20 G01 G91 Y2=5 F100\nN30 G74 Y1\n", "p.nc"), portal)
    assert [(d.line, d.column, d.code) for d in found] == [(1, 9, "LIS602"), (2, 13, "LIS602")]
    assert "Y2 is the gantry slave of Y" in found[0].message and "program Y instead" in found[0].message
    assert findings(portal, "N10 G74 Y1\nN20 G01 G91 Y5 F100\n") == []


def test_a_gantry_slave_that_goes_by_its_own_name_homed_before_its_master(gantry):
    assert findings(gantry, "N10 G74 Y2=1 Y2\nN20 G74 Y2=1\n") == [(1, 9, "LIS605")]


def test_homing_state_between_blocks(portal, gantry):
    # The slave Y2 is referenced with its master (gantry_slave_no_homing): it may move after N10.
    assert findings(gantry, "N10 G74 Y1\nN20 G01 G91 Y2=5 F100\nN30 M30\n") == []
    # B has an absolute encoder: it may move at once. C is DISABLED: its G74 fails, but it is absolute too.
    assert findings(portal, "N10 G74 Y1\nN20 G01 G91 B10 F100\nN30 M30\n") == []
    # A move between two G74 blocks: X homed in N10 may move, A homed only in N30 may not yet.
    assert findings(portal, "N10 G74 X1\nN20 G00 X5 A10\nN30 G74 A1\n") == [(2, 12, "LIS606")]


def test_a_slave_with_its_master_in_the_same_group_is_fine(gantry):
    assert findings(gantry, "N10 G74 Y1 Y2=1\n") == []
    assert findings(gantry, "N10 G74 Y2=2 Y1\n") == []  # the master at step 1, the slave at step 2


def test_the_manuals_program_on_the_four_axis_machine():
    machine = build_machine(SDK4)
    text = "N10 G74 Z1\nN15 G01 G90 Z200 F500\nN20 G74 X1 Y1 A2 B2 S3\nN30 M30\n"
    assert findings(machine, text) == [(3, 15, "LIS602"), (3, 18, "LIS602")]


def test_lint_with_machine_in_the_cli_concise():
    bad = FIXTURES / "rules" / "LIS604" / "bad.nc"
    result = cli("lint", str(bad), "--machine", str(PORTAL), "--format", "concise")
    assert result.returncode == 1, result.stderr
    assert result.stdout.splitlines()[0].startswith(f"{bad}:3:15: LIS604 [error] C must not be homed")


@pytest.mark.parametrize("fmt", ["json", "sarif", "github", "gitlab", "junit", "full"])
def test_program_findings_in_every_format(fmt):
    bad = FIXTURES / "rules" / "LIS607" / "bad.nc"
    result = cli("lint", str(bad), "--machine", str(PORTAL), "--format", fmt, "--exit-zero")
    assert result.returncode == 0, result.stderr
    assert "LIS607" in result.stdout
    if fmt == "json":
        found = [d for d in json.loads(result.stdout)["diagnostics"] if d["code"] == "LIS607"]
        assert [(d["line"], d["column"]) for d in found] == [(3, 15)]


def test_lists_and_programs_in_one_run():
    bad = FIXTURES / "rules" / "LIS606" / "bad.nc"
    listing = FIXTURES / "rules" / "LIS302" / "bad.lis"
    result = cli("lint", str(bad), str(listing), "--machine", str(PORTAL), "--format", "concise")
    codes = {line.split(": ")[1].split(" ")[0] for line in result.stdout.splitlines() if ": LIS" in line}
    assert {"LIS606", "LIS302"} <= codes


def test_a_program_without_machine_is_a_usage_error():
    result = cli("lint", str(FIXTURES / "machines" / "portal" / "rfp.nc"))
    assert result.returncode == 2
    assert "give its start-up list with --machine hochlauf.lis" in result.stderr
    assert "Traceback" not in result.stderr


def test_a_machine_that_cannot_be_built_is_one_line(tmp_path):
    startup = tmp_path / "hochlauf.lis"
    startup.write_text("achs_mds[0] missing.lis\nEnde\n")
    result = cli("lint", str(FIXTURES / "machines" / "portal" / "rfp.nc"), "--machine", str(startup))
    assert result.returncode == 2
    assert f"--machine: {startup}:1: `achs_mds[0]` names the axis list `missing.lis`" in result.stderr
    assert "Traceback" not in result.stderr


def test_a_program_that_is_missing(tmp_path):
    result = cli("lint", str(tmp_path / "rfp.nc"), "--machine", str(PORTAL))
    assert result.returncode == 2
    assert "rfp.nc: no such file or directory" in result.stderr


def test_explain_a_machine_as_json():
    program = FIXTURES / "machines" / "portal" / "rfp.nc"
    result = cli("explain", str(PORTAL), "--program", str(program), "--format", "json")
    assert result.returncode == 0, result.stderr
    report = json.loads(result.stdout)
    axes = {row["name"]: row for row in report["axes"]}
    assert list(axes) == ["X", "Y", "Z", "A", "B", "C", "S"]  # the channel's axes: not the gantry slave Y2
    others = {row["name"]: row for row in report["other_axes"]}
    assert list(others) == ["Y2"] and others["Y2"]["logical_number"] == 7
    assert others["Y2"]["gantry"] == {"role": "slave", "master": "Y", "homes_with_master": True}
    assert axes["Y"]["gantry"] == {"role": "master", "slaves": ["Y2"]}
    assert axes["C"]["strategy"]["id"] == "disabled" and axes["S"]["axis_type"] == "spindle"
    assert axes["X"]["drive_type"] == 1 and axes["B"]["drive_type"] == 8
    # rfp.nc: N10 G74 Z1, N15 G01 G90 Z200 F500, N20 G74 X1 Y1 A2 S3
    assert axes["Z"]["homed"] == "line 3 (N10), step 1"
    assert axes["X"]["homed"] == axes["Y"]["homed"] == "line 5 (N20), step 1"
    assert others["Y2"]["homed"] == "line 5 (N20), step 1, with its master Y"
    assert axes["A"]["homed"] == "line 5 (N20), step 2"
    assert axes["S"]["homed"] == "line 5 (N20), step 3"
    assert axes["B"]["homed"].startswith("not needed")
    blocks = report["program"]["blocks"]
    assert [b["kind"] for b in blocks] == ["homing", "move", "homing"]
    assert blocks[1]["targets"] == {"Z": 200.0} and blocks[1]["feed_mm_min"] == 500.0
    assert blocks[2]["groups"] == [
        {"sequence": 1, "axes": ["X", "Y"]},
        {"sequence": 2, "axes": ["A"]},
        {"sequence": 3, "axes": ["S"]},
    ]
    assert report["program"]["findings"] == []


def test_explain_a_machine_as_text():
    result = cli("explain", str(SDK4), "--program", str(FIXTURES / "machines" / "sdk4" / "rfp.nc"))
    assert result.returncode == 0, result.stderr
    assert "names from channel 1" in result.stdout
    assert "drive-controlled homing" in result.stdout  # the spindle S
    assert "line 5 N20: G74 homes X, Y; then S" in result.stdout
    assert "line 4 N15: G01 F500 G90 Z200" in result.stdout


def test_explain_shows_the_portals_gantry_slave_beside_the_channel_s_axes():
    result = cli("explain", str(PORTAL), "--program", str(FIXTURES / "machines" / "portal" / "rfp.nc"))
    assert result.returncode == 0, result.stderr
    assert (
        "Gantry slave, no axis of this channel: Y2 (" in result.stdout
        and "logical axis 7) moves with its master Y; homed: line 5 (N20), step 1, with its master Y"
        in " ".join(result.stdout.split())
    )
    assert "Not named in this channel" not in result.stdout


def test_explain_says_a_slave_outside_the_channel_with_a_homing_of_its_own_homes_after_its_master(tmp_path):
    from achslint.machine.explain import explain_startup

    folder = tmp_path / "portal"
    shutil.copytree(FIXTURES / "machines" / "portal", folder)
    slave = folder / "listen" / "achsmds7.lis"
    text = slave.read_text(encoding="latin-1")
    slave.write_text(text.replace("gantry_slave_no_homing             1", "gantry_slave_no_homing 0"))
    report = explain_startup(folder / "listen" / "hochlauf.lis", program=folder / "rfp.nc")
    (row,) = report["other_axes"]
    assert row["gantry"] == {"role": "slave", "master": "Y", "homes_with_master": False}
    assert row["homed"] == "line 5 (N20), step 1, after its master Y"


def test_explain_program_needs_a_start_up_list():
    result = cli(
        "explain", str(FIXTURES / "machines" / "sdk4" / "listen" / "achsmds1.lis"), "--program", "x.nc"
    )
    assert result.returncode == 2 and "--program goes with a start-up list" in result.stderr


def test_noqa_in_program_comments(tmp_path):
    # One LIS606 per line below; a `noqa` in a comment of the line (either comment form) suppresses it,
    # one that names another code does not, and a comment line `; achslint: noqa: CODE` covers the program.
    body = (
        "N10 G01 G90 Z200 F500 (noqa: LIS606)\n"
        "N20 G01 G90 Z210 F500 ; lift first, noqa: LIS606\n"
        "N30 G01 G90 Z220 F500 (noqa: LIS602)\n"
        "N40 G01 G90 Z230 F500 (noqa)\n"
        "N50 G01 G90 Z240 F500\n"
        "N60 G74 Z1\n"
        "N70 M30\n"
    )
    program = tmp_path / "rfp.nc"

    def reported(text: str) -> list[tuple[int, str]]:
        program.write_text(text)
        result = cli("lint", str(program), "--machine", str(PORTAL), "--format", "json", "--exit-zero")
        return [(d["line"], d["code"]) for d in json.loads(result.stdout)["diagnostics"]]

    # Line 3's `noqa: LIS602` suppresses nothing, so it is itself a finding (LIS009), as in a list.
    assert reported(body.replace(" (noqa: LIS606)", "").replace(" ; lift first, noqa: LIS606", "")) == [
        (1, "LIS606"),
        (2, "LIS606"),
        (3, "LIS606"),
        (3, "LIS009"),
        (5, "LIS606"),
    ]  # without the directives (line 4's bare noqa stays): every move of Z before N60
    assert reported(body) == [(3, "LIS606"), (3, "LIS009"), (5, "LIS606")]
    assert reported("; achslint: noqa: LIS606\n" + body) == [(4, "LIS009")]
    assert reported("(achslint: noqa: LIS602)\n" + body) == [
        (1, "LIS009"),
        (4, "LIS606"),
        (4, "LIS009"),
        (6, "LIS606"),
    ]


def _axis(name: str, number: int, text: str, master: str | None = None) -> MachineAxis:
    data = f"kopf.achs_nr {number}\nkopf.log_achs_name {name}\n{text}Ende\n".encode()
    return MachineAxis(
        name, number, None, data, None, resolve_bytes(data, f"{name}.lis"), gantry_master=master
    )


def test_what_a_program_counts_as_homed_follows_the_axis_strategy():
    """Homed before any G74: an absolute encoder, also on a gantry slave whose strategy is "homed with its
    master" (P-AXIS-00014, P-AXIS-00074). Homed by the master's G74: a slave without homing of its own, not
    one that homes itself."""
    master = _axis("X1", 1, "kenngr.antr_typ 1\n")
    absolute = _axis(
        "X2", 2, "kenngr.gantry_ax_nr 1\nkenngr.gantry_slave_no_homing 1\nkenngr.abs_pos_gueltig 1\n", "X1"
    )
    follows = _axis("X3", 3, "kenngr.gantry_ax_nr 1\nkenngr.gantry_slave_no_homing 1\n", "X1")
    own = _axis("X4", 4, "kenngr.gantry_ax_nr 1\n", "X1")
    machine = ChannelView(
        None, {a.name: a for a in (master, absolute, follows, own)}, [("X1", n) for n in ("X2", "X3", "X4")]
    )
    assert classify(absolute.resolved).id == "gantry_slave"
    assert findings(machine, "N10 G01 X2=5 F100\n") == []
    assert findings(machine, "N10 G01 X3=5 F100\n") == [(1, 9, "LIS606")]
    assert findings(machine, "N10 G74 X1=1\nN20 G01 X3=5 F100\n") == []
    assert findings(machine, "N10 G74 X1=1\nN20 G01 X4=5 F100\n") == [(2, 9, "LIS606")]


def test_explain_of_a_long_program_reads_repeated_blocks_as_one_line_and_stops_at_a_limit(tmp_path):
    """A block that reads like the one before it joins its line; the text form stops after its limit and
    says how many blocks it leaves to `--format json`, which keeps them all."""
    from achslint.output.explain import PROGRAM_LINES

    same = [f"N{n} G74 X1" for n in range(1, 501)]  # 500 blocks that home X: one line
    mixed = [f"N{n} G01 G90 X{n} F100" for n in range(501, 501 + PROGRAM_LINES + 50)]  # each its own line
    program = tmp_path / "long.nc"
    program.write_text("%long\n" + "\n".join(same + mixed) + "\nM30\n")
    result = cli("explain", str(SDK4), "--program", str(program))
    assert result.returncode == 0, result.stderr
    assert "  line 2 N1 to line 501 N500, 500 blocks: G74 homes X\n" in result.stdout
    assert "  line 502 N501: G01 F100 G90 X501\n" in result.stdout
    shown = [line for line in result.stdout.splitlines() if line.startswith("  line ")]
    assert len(shown) == PROGRAM_LINES
    assert "  … 51 more blocks not shown (`--format json` lists every block)" in result.stdout
    every = json.loads(cli("explain", str(SDK4), "--program", str(program), "--format", "json").stdout)
    assert len(every["program"]["blocks"]) == 500 + PROGRAM_LINES + 50

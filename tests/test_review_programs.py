"""Review of the NC program reader, program lint (LIS6xx), `explain --program` and the machine dry-run:
programs that an ISG CNC runs, and places where a finding, `explain` and the dry-run must agree."""

from __future__ import annotations

import pytest

from achslint.linting.program import check_program
from achslint.machine.explain import explain_machine
from achslint.machine.model import HomingBlock, MoveBlock, SkippedBlock
from achslint.machine.program import read_program
from achslint.machine.run import run_machine
from achslint.machine.scenario import parse_machine_scenario

from .conftest import PORTAL_STARTUP as PORTAL


def codes(machine, text: str) -> list[tuple[int, int, str]]:
    return [(d.line, d.column, d.code) for d in check_program(read_program(text.encode(), "p.nc"), machine)]


def homed(machine, text: str) -> dict[str, str]:
    report = explain_machine(machine, read_program(text.encode(), "p.nc"))
    return {row["name"]: row["homed"] for row in report["axes"]}


# -- the reader --------------------------------------------------------------------------------------


def test_a_control_command_after_a_block_number_is_skipped_not_an_error(portal):
    # `N10 #MSG[...]` is an ordinary ISG block: a control command with a block number. The reader passes
    # over `#` at the start of a line; after `N10` it must do the same, not call the block unreadable.
    program = read_program(b'N10 #MSG["homing"]\nN20 G74 Z1\nN30 M30\n', "p.nc")
    assert program.problems == []
    assert isinstance(program.blocks[0], SkippedBlock)
    assert isinstance(program.blocks[1], HomingBlock)
    assert codes(portal, 'N10 #MSG["homing"]\nN20 G74 Z1\nN30 M30\n') == []


def test_parameter_and_spindle_speed_words_in_a_move_block_are_no_axes(portal):
    # `P1=2` assigns an arithmetic parameter and `S1=1000` is the speed of spindle S1: neither is an axis a
    # block moves (P and S are no axis addresses outside G74), so no LIS602 and no failing dry-run.
    text = "N10 G74 Z1\nN20 G01 G90 Z200 F500\nN30 P1=2\nN40 S1=1000\nN50 M30\n"
    program = read_program(text.encode(), "p.nc")
    assert not any(isinstance(b, MoveBlock) for b in program.blocks[2:])
    assert codes(portal, text) == []
    run = run_machine(portal, program, parse_machine_scenario({}, "scenario"))
    assert run.failure is None


# -- explain agrees with the findings and the dry-run ---------------------------------------------------


def test_explain_does_not_call_an_ignore_abs_pos_axis_homed_by_g74(portal):
    # LIS607 says B is not homed (IGNORE_ABS_POS); explain must not say the G74 homes it.
    text = "N10 G74 X1 B1\nN20 M30\n"
    assert (1, 12, "LIS607") in codes(portal, text)
    rows = homed(portal, text)
    assert rows["X"] == "line 1 (N10), step 1"
    assert "line 1" not in rows["B"]


def test_explain_homes_nothing_at_or_after_the_block_where_the_cnc_stops(portal):
    # C is DISABLED: the CNC stops the program at C (LIS604, P-ERR-50686); Y after it is never homed, and
    # neither is C. X in the group before C is.
    text = "N10 G74 X1 C2 Y3\nN20 G74 Z1\nN30 M30\n"
    assert (1, 12, "LIS604") in codes(portal, text)
    rows = homed(portal, text)
    assert rows["X"] == "line 1 (N10), step 1"
    for name in ("C", "Y", "Z"):
        assert not rows[name].startswith("line"), (name, rows[name])
    run = run_machine(portal, read_program(text.encode(), "p.nc"), parse_machine_scenario({}, "scenario"))
    assert run.axes["X"].outcome == "homed"
    assert run.axes["Y"].outcome == "not_run" and run.axes["Z"].outcome == "not_run"


def test_explain_homes_nothing_of_a_block_naming_an_unknown_axis(portal):
    # LIS602: the CNC stops the program at this block, so X in it is not homed either (as the dry-run says).
    text = "N10 G74 X1 Q1\nN20 M30\n"
    assert codes(portal, text) == [(1, 12, "LIS602")]
    assert not homed(portal, text)["X"].startswith("line")
    run = run_machine(portal, read_program(text.encode(), "p.nc"), parse_machine_scenario({}, "scenario"))
    assert run.axes["X"].outcome != "homed"


# -- the dry-run's messages --------------------------------------------------------------------------


def test_a_homed_axis_at_its_limit_switch_is_not_called_unhomed(portal):
    # Z is homed in N10; the scenario puts its limit switch inside its software limits, so N30 hits it. The
    # failure must not say Z is not homed.
    text = "N10 G74 Z1\nN20 G01 G90 Z0 F1000\nN30 M30\n"
    scenario = parse_machine_scenario({"axes": {"Z": {"limit_switches": [-50.0, 410.0]}}}, "scenario")
    run = run_machine(portal, read_program(text.encode(), "p.nc"), scenario)
    assert run.axes["Z"].homed
    assert run.failure is not None and run.failure.axis == "Z"
    assert "not homed" not in run.failure.reason


# -- a parameter list given as the program -----------------------------------------------------------


@pytest.mark.parametrize("name", ["achsmds1.lis", "hochlauf.lis", "sda_mds1.lis"])
def test_a_parameter_list_given_as_the_program_is_one_finding(portal, name):
    # Every line of a list would be an LIS601 of its own (hundreds); one finding says what the file is.
    data = (PORTAL.parent / name).read_bytes()
    found = check_program(read_program(data, "p.nc"), portal)
    assert [(d.line, d.code) for d in found] == [(1, "LIS601")]
    assert "parameter list" in found[0].message


# -- outside this review's files ----------------------------------------------------------------------


def test_explain_text_writes_an_extended_axis_name_with_its_equals_sign():
    from achslint.output.explain import _block_words

    """`Y2=5` printed as `Y25` (axis Y to 25), and large values lost digits (`:g`)."""
    block = {"kind": "move", "rapid": False, "feed_mm_min": 100.0, "absolute": True, "targets": {"Y2": 5.0}}
    assert _block_words(block) == "G01 F100 G90 Y2=5"
    block["targets"] = {"X": 1234567.5}
    assert _block_words(block) == "G01 F100 G90 X1234567.5"


def test_the_manuals_example_move_after_homing_runs_on_the_assumed_geometry(portal):
    """Assumed limit switches lie beyond the software limits of the homed frame once an axis is homed: they
    were placed 10 beyond them in actual values, so the portal's Z (reference position 395 mm) had a switch
    at -110 mm actual, inside its software limits, and the manual's `G01 Z0` after homing hit it."""
    text = "N10 G74 Z1\nN15 G01 G90 Z200 F500\nN20 G74 X1 Y1\nN30 G01 X0 Y20 Z0 F1000\nN40 M30\n"
    run = run_machine(portal, read_program(text.encode(), "p.nc"), parse_machine_scenario({}, "scenario"))
    assert run.failure is None

"""A fresh look at the homing-program reader's ISG syntax: forms of the TF5200 programming manual that were
still read as defects (a false LIS601 error), and places where a finding, `explain` and the dry-run told
different stories. Each test failed before its fix."""

from __future__ import annotations

from achslint.linting.program import check_program
from achslint.machine.build import build_machine
from achslint.machine.model import HomingBlock, SkippedBlock
from achslint.machine.program import read_program

from .conftest import FIXTURES

PORTAL = FIXTURES / "machines" / "portal" / "listen" / "hochlauf.lis"


def read(text: str):
    return read_program(text.encode(), "p.nc")


def codes(text: str) -> list[tuple[int, str]]:
    return [(d.line, d.code) for d in check_program(read(text), build_machine(PORTAL))]


# -- #VAR … #ENDVAR: declarations of variables ("Global, not valid after part program end (V.P.)" and
# "Local, valid throughout subroutine (V.L.)": a name alone, or with a type and an initial value) ----------


def test_variable_declarations_are_no_defect():
    program = read(
        "#VAR\nV.P.VAR_5\nV.L.LOC_VAR2 : UNS32 = 200\nV.L.LOC_VAR4 : BOOLEAN\n#ENDVAR\nN10 G74 X1\nN20 M30\n"
    )
    assert program.problems == [], [p.message for p in program.problems]
    assert [type(b).__name__ for b in program.blocks].count("HomingBlock") == 1
    assert program.end is not None and program.end.line == 7


def test_after_endvar_the_lines_are_blocks_again():
    program = read("#VAR\nV.P.A = 1\n#ENDVAR\nN10 G74 X1\nN20 G74 Q\n")
    assert [p.at.line for p in program.problems] == [5]  # `Q` without a number is still a defect


def test_declarations_and_a_comment_section_inside_a_local_subroutine():
    text = (
        "%L UP1\n#VAR\nV.L.A : REAL = 2\n#ENDVAR\nN1 #COMMENT BEGIN\nthis is free text, not code!\n"
        "#COMMENT END\nN2 G74 X1\nN9 M17\n%MAIN\nN10 LL UP1\nN20 M30\n"
    )
    program = read(text)
    assert program.problems == [], [p.message for p in program.problems]
    assert codes(text) == []
    # the subroutine's blocks run only where it is called: none of them homes at the start
    assert not any(isinstance(b, HomingBlock) for b in program.blocks)


# -- an address with a variable written right after it (`N20 XV.P.VAR_5`, the manual's own example) -------


def test_an_address_followed_by_a_variable():
    program = read("N10 G74 X1\nN20 G01 G90 XV.P.VAR_5 F100\nN30 M30\n")
    assert program.problems == [], [p.message for p in program.problems]
    block = program.blocks[1]
    assert isinstance(block, SkippedBlock) and "computed position" in block.reason
    assert [w.name for w in block.moves] == ["X"]


def test_an_address_followed_by_a_variable_in_lower_case():
    program = read("n10 g74 x1\nn20 g01 g90 xv.l.pos f100\n")
    assert program.problems == [], [p.message for p in program.problems]
    assert [w.name for w in program.blocks[1].moves] == ["X"]  # type: ignore[union-attr]


# -- a G74 naming an axis the channel does not have: nothing of the block runs ---------------------------


def test_the_dry_run_homes_nothing_of_a_g74_that_names_an_unknown_axis():
    from achslint.machine.explain import explain_machine
    from achslint.machine.run import run_machine
    from achslint.machine.scenario import parse_machine_scenario

    machine = build_machine(PORTAL)
    program = read("N10 G74 Z1 Q2\nN20 M30\n")
    assert codes("N10 G74 Z1 Q2\nN20 M30\n") == [(1, "LIS602")]  # "the CNC stops the program at this block"
    rows = {row["name"]: row["homed"] for row in explain_machine(machine, program)["axes"]}
    assert rows["Z"].startswith("not: the CNC stops the program at line 1")
    run = run_machine(machine, program, parse_machine_scenario({}, "scenario"))
    assert run.failure is not None and "Q, which is not an axis" in run.failure.reason
    assert run.axes["Z"].outcome != "homed"  # it homed Z in step 1 before failing at step 2
    assert [g.outcome for g in run.blocks[0].groups] == ["not_run", "failed"]


def test_a_gantry_slave_is_not_said_to_be_not_commanded_when_its_masters_block_is_not_simulated():
    from achslint.machine.explain import explain_machine
    from achslint.machine.run import run_machine
    from achslint.machine.scenario import parse_machine_scenario

    machine = build_machine(PORTAL)
    for text, outcome in [
        ("N10 G74 Z[P1]\nN20 G74 Y1\nM30\n", "not_simulated"),
        ("N10 G74 Q1\nN20 G74 Y1\n", "not_run"),
    ]:
        program = read(text)
        report = explain_machine(machine, program)
        rows = {row["name"]: row.get("homed", "") for row in report["axes"] + report["other_axes"]}
        run = run_machine(machine, program, parse_machine_scenario({}, "scenario"))
        # the slave Y2 is commanded with its master Y (explain: "with its master Y" or "not")
        assert "master Y" in rows["Y2"] or rows["Y2"].startswith("not:"), rows["Y2"]
        assert (run.axes["Y"].outcome, run.axes["Y2"].outcome) == (outcome, outcome), text


def test_a_g74_naming_an_axis_twice_homes_nothing_in_lint_explain_and_dry_run():
    # LIS603 is an error: the CNC stops at the block. The dry-run homed X, then Y, then X again when the two
    # mentions had different orders (it failed only for equal ones), and explain said both were homed.
    from achslint.machine.explain import explain_machine
    from achslint.machine.run import run_machine
    from achslint.machine.scenario import parse_machine_scenario

    machine = build_machine(PORTAL)
    for text in ("N10 G74 X1 Y2 X3\nN20 M30\n", "N10 G74 X1 Y1 X1\nN20 M30\n"):
        assert codes(text) == [(1, "LIS603")]
        program = read(text)
        rows = {row["name"]: row["homed"] for row in explain_machine(machine, program)["axes"]}
        assert rows["X"].startswith("not: the CNC stops the program at line 1"), rows["X"]
        assert rows["Y"].startswith("not: the CNC stops the program at line 1"), rows["Y"]
        run = run_machine(machine, program, parse_machine_scenario({}, "scenario"))
        assert run.failure is not None and "names X twice" in run.failure.reason
        assert run.axes["X"].outcome != "homed" and run.axes["Y"].outcome != "homed", text

"""ISG NC syntax in a homing program: what the decoder reads (TF5200 programming manual: expressions in
brackets, parameters and variables, assignments, subroutine and macro calls, control statements) is read
without LIS601, and what the reader does not follow leaves no finding, `explain` or dry-run claiming what
may not happen."""

from __future__ import annotations

import re

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from achslint.linting.program import check_program
from achslint.machine.explain import explain_machine
from achslint.machine.model import HomingBlock, MoveBlock, SkippedBlock
from achslint.machine.program import read_program
from achslint.machine.run import run_machine
from achslint.machine.scenario import parse_machine_scenario

from .conftest import PORTAL_STARTUP as PORTAL
from .conftest import examples, run_cli

# The program of the report: every block is ISG syntax the decoder reads.
REPORTED = "N10 G74 X1 Y2\nN20 X[P1*2]\nN30 P1 = 2\nN35 P2 = P1 + 1\nN40 G01 X10 F1000\nN45 LL X20\nM30\n"


def read(text: str):
    return read_program(text.encode(), "p.nc")


def codes(machine, text: str) -> list[tuple[int, str]]:
    return [(d.line, d.code) for d in check_program(read(text), machine)]


def homed(machine, text: str) -> dict[str, str]:
    report = explain_machine(machine, read(text))
    return {row["name"]: row["homed"] for row in report["axes"]}


def dry_run(machine, text: str):
    return run_machine(machine, read(text), parse_machine_scenario({}, "scenario"))


# -- the reported program ------------------------------------------------------------------------------


def test_the_reported_program_has_no_lis601(portal):
    program = read(REPORTED)
    assert program.problems == []
    assert [type(b).__name__ for b in program.blocks] == [
        "HomingBlock",
        "SkippedBlock",
        "SkippedBlock",
        "SkippedBlock",
        "MoveBlock",
        "SkippedBlock",
    ]
    reasons = [b.reason for b in program.blocks if isinstance(b, SkippedBlock)]
    assert reasons == [
        "X[P1*2]: a computed position is not simulated",
        "a parameter assignment: not simulated",
        "a parameter assignment: not simulated",
        "LL X20: a subroutine call is not followed",
    ]
    assert program.end is not None and program.end.line == 7
    assert "LIS601" not in {code for _, code in codes(portal, REPORTED)}


def test_the_reported_program_through_the_cli(tmp_path):
    program = tmp_path / "p.nc"
    program.write_text(REPORTED, encoding="utf-8")
    result = run_cli("lint", str(program), "--machine", str(PORTAL))
    assert b"LIS601" not in result.stdout, result.stdout.decode()


# -- every form of the manual, read without LIS601 -------------------------------------------------------

# (block, what the reader makes of it: a kind and a part of the reason, or the words it reads)
FORMS = [
    ("N20 X[P1*2]", "computed position"),
    ("G01 X[-2*P1+3] F100", "computed position"),
    ("G01 X P1*SIN [P2*30] F100", "computed position"),
    ("G01 XP1*SIN[P2*30] F100", "computed position"),
    ("G01 X[[SIN[P1*30.00] + P2] / P5] F100", "computed position"),
    ('G01 X[-2 * "STRING1" + "STRING2"] F100', "computed position"),
    ("G01 X[V.P.POS + V.A.ABS.X] F100", "computed position"),
    ("G01 X[DEXP[2]] Y[100+SIN[P10+PP20]] F100", "computed position"),
    ("G01 Y2=[P1] F100", "computed position"),
    ("G74 X[P1] Y1", "computed homing order"),
    ("P1 = 10", "parameter assignment"),
    ("P1=10", "parameter assignment"),
    ("P1 = P2 + P3 * [P4 - 1]", "parameter assignment"),
    ("P5 = [[SIN[R1*30.00] + P2] / P5]", "parameter assignment"),
    ("N110 P1 = 20  P2 = 40", "parameter assignment"),
    ("N120 PP1 = 50", "parameter assignment"),
    ("N130 PP2 = PP1", "parameter assignment"),
    ("N120 P[P1 + 5] = 0.0", "parameter assignment"),
    ("P100[50] = 2**P3", "parameter assignment"),
    ("P1 = 11 MOD 3", "parameter assignment"),
    ("P1 = ABS [P2 - P4]", "parameter assignment"),
    ("P1 = SQRT [SQR[P2]+SQR[P3]]", "parameter assignment"),
    ("V.P.NAME = 5", "variable assignment"),
    ("V.L.ARR[2] = V.G.OFFSET + 1", "variable assignment"),
    ("V.CYC.DEPTH = P1", "variable assignment"),
    ('N10 "STRING1" = "COS[\\"STRING2\\"]"', "macro definition"),
    ('N20 "STRING2" = "5 * 12"', "macro definition"),
    ("N200 LL UP1", "subroutine call"),
    ("N200 L gup_1.nc", "subroutine call"),
    ("N250 L D:\\prog\\ini_1.nc", "subroutine call"),
    ("N110 L4712", "subroutine call"),
    ("N110 LL V.E.LUP", "subroutine call"),
    ("N200 L V.E.GUP", "subroutine call"),
    ('N30 "MOVE1"', "macro call"),
    ("$IF P1 == 1", "control statement"),
    ("N110 $FOR P1 = 10,20,1", "control statement"),
    ("$GOTO N50", "control statement"),
    ("$ENDIF", "control statement"),
    ('N10 #MSG["homing; (now)"]', "control command"),
    ("G01 G[P1] X1 F100", "computed G code"),
    ("M[P2]", "computed M code"),
    ("N300 (comment (nested comment)) G74 X1", None),
    ("G74 X 1 Y 2", None),
]


@pytest.mark.parametrize(("block", "reason"), FORMS)
def test_every_form_of_the_manual_is_read_without_a_problem(block, reason):
    program = read(f"N5 G90\n{block}\n")
    assert program.problems == [], [p.message for p in program.problems]
    (read_block,) = program.blocks
    if reason is None:
        assert isinstance(read_block, HomingBlock), read_block
    else:
        assert isinstance(read_block, SkippedBlock) and reason in read_block.reason, read_block


def test_blanks_between_an_address_and_its_value():
    (block,) = read("G74 X 1 Y 2\n").blocks
    assert isinstance(block, HomingBlock)
    assert [(w.name, w.value) for w in block.words] == [("X", 1.0), ("Y", 2.0)]


def test_a_comment_over_several_lines_makes_no_block():
    program = read("#COMMENT BEGIN\nthis @ is [ not ( NC text\n#COMMENT END\nN10 G74 X1\n")
    assert program.problems == []
    assert [type(b).__name__ for b in program.blocks] == ["SkippedBlock", "HomingBlock"]


def test_a_local_subroutine_runs_where_it_is_called_not_at_the_start(portal):
    text = "%L UP1\nN1 G74 X1\nN2 M17\n%MAIN\nN10 G01 G90 X10 F100\nN20 LL UP1\nN30 M30\n"
    program = read(text)
    assert program.problems == []
    assert not any(isinstance(b, HomingBlock) for b in program.blocks)  # G74 X1 runs only when called
    assert isinstance(program.blocks[4], MoveBlock)
    # X is moved before any call: nothing has homed it yet.
    assert codes(portal, text) == [(5, "LIS606")]


def test_a_computed_word_keeps_its_axis_for_the_findings_that_need_only_the_name(portal):
    assert codes(portal, "N10 G74 X[P1] Q1\nN20 M30\n") == [(1, "LIS602")]
    assert codes(portal, "N10 G74 X[P1] C1\nN20 M30\n") == [(1, "LIS604")]
    assert codes(portal, "N10 G74 X[P1] X2\nN20 M30\n") == [(1, "LIS603")]
    # A move to a computed position moves its axis: before any G74 it is not homed.
    found = check_program(read("N10 G01 G90 Z[P1] F100\nN20 G74 Z1\n"), portal)
    assert [(d.line, d.code) for d in found] == [(1, "LIS606")]
    assert "moves it (Z[P1])" in found[0].message
    # A G74 with a computed order homes its axes all the same.
    assert codes(portal, "N10 G74 Z[P1]\nN20 G01 G90 Z10 F100\n") == []


def test_a_gantry_slave_in_a_g74_with_a_computed_order(gantry):
    # the master not homed before, nor named in the block: the slave homes alone
    assert codes(gantry, "N10 G74 Y2=[P1]\nN20 M30\n") == [(1, "LIS605")]
    # master and slave in one block, in an order computed when the program runs: not known to be wrong
    assert codes(gantry, "N10 G74 Y2=[P1] Y1\nN20 M30\n") == []


# -- real defects stay LIS601 ------------------------------------------------------------------------------

DEFECTS = [
    ("G74 X[", "not closed with `]`"),
    ("G01 X[P1*2 F100", "not closed with `]`"),
    ("G01 X[[P1] F100", "not closed with `]`"),
    ("G01 X[] F100", "nothing between `[` and `]`"),
    ("P1 =", "nothing to assign after `=`"),
    ("P1 = *", "nothing to assign after `=`"),
    ("L", "names no subroutine"),
    ('G01 X10 "open', "is not closed"),
    ("V.P.NAME", "must be assigned"),
    ("G74 X1 Y", "has no number after it"),
    ("G01 X1 @ F10", "is not an NC word"),
    ("G74", "G74 names no axis"),
    ("G74 X0", "a whole number from 1 up"),
]


@pytest.mark.parametrize(("block", "message"), DEFECTS)
def test_real_defects_are_still_lis601(portal, block, message):
    found = check_program(read(f"{block}\nM30\n"), portal)
    assert [d.code for d in found if d.line == 1] and all(d.code == "LIS601" for d in found), found
    assert any(message in d.message for d in found), [d.message for d in found]


def test_an_unclosed_bracket_is_pointed_at_from_its_word():
    (problem,) = read("N10 G01 X[P1*2 F100\n").problems
    assert (problem.at.line, problem.at.column) == (1, 9)
    assert problem.message.startswith("`X[P1*2 F100`: the `[` is not closed with `]`")


# -- what is not followed ---------------------------------------------------------------------------------

NOT_FOLLOWED = ["N15 L sub.nc", "N15 LL SUB", 'N15 "MACRO"', "N15 G[P1]", "/N15 G74 Z1", "N15 $GOTO N10"]


@pytest.mark.parametrize("block", NOT_FOLLOWED)
def test_no_lis606_after_a_part_that_may_have_homed_the_axis(portal, block):
    # Z is homed only by the G74 after the move; what runs at line 2 may home it first (or jump back).
    text = f"N10 G74 X1\n{block}\nN20 G01 G90 Z10 F100\nN30 G74 Z1\nN40 M30\n"
    assert "LIS606" not in {code for _, code in codes(portal, text)}
    assert codes(portal, text.replace(block + "\n", "")) == [(2, "LIS606")]


def test_a_branch_passes_blocks_by_but_homes_nothing_above(portal):
    # No G74 above line 6 names Y, on either way through the branch: the move of Y is before its homing.
    text = (
        "N10 G74 Z1\n$IF P1 == 1\nN20 G74 X1\n$ENDIF\nN25 G01 G90 X5 F500\nN30 G01 G90 Y10 F500\nN40 G74 Y1\n"
    )
    assert codes(portal, text) == [(6, "LIS606")]
    rows = homed(portal, text)
    assert rows["Z"] == "line 1 (N10), step 1"
    assert rows["X"].startswith("perhaps: line 3 (N20), step 1 (the program is not followed past line 2")
    assert rows["Y"].startswith("perhaps: line 7 (N40)")
    assert rows["A"] == "not by this program"  # no G74 names it, and nothing is called


def test_a_loop_may_run_a_later_g74_first(portal):
    text = "N10 $FOR P1 = 1,2,1\nN20 G01 G90 Y10 F500\nN30 G74 Y1\nN40 $ENDFOR\n"
    assert "LIS606" not in {code for _, code in codes(portal, text)}


def test_the_modal_state_is_not_known_after_a_call(portal):
    text = "N10 G74 X1 Y1\nN20 G01 G90 F500\nN30 LL SUB\nN40 X10\nN50 G01 Y10\nN60 G00 G91 X1\n"
    program = read(text)
    assert program.problems == []  # no `G01 without a feed rate`: the subroutine may have set F
    kinds = [type(b).__name__ for b in program.blocks]
    assert kinds == ["HomingBlock", "SkippedBlock", "SkippedBlock", "SkippedBlock", "MoveBlock"]
    assert (
        program.blocks[2].reason
        == "an axis position: the motion mode (G00/G01) in force after line 3 (`N30 LL SUB`) is not known"
    )
    assert "whether G90 or G91 is in force after line 3" in program.blocks[3].reason
    assert program.blocks[4].absolute is False and program.blocks[4].rapid


def test_a_goto_target_does_not_keep_the_modal_state_read_above_it():
    text = "N10 G01 G91 F100\nN20 $IF P1 == 1\nN30 $GOTO N60\nN40 $ENDIF\nN50 G90\nN60 X10\n"
    last = read(text).blocks[-1]
    assert isinstance(last, SkippedBlock) and "at N60 (a `$GOTO` may jump there)" in last.reason


def test_an_end_inside_a_branch_does_not_end_the_reading(portal):
    text = "N10 G74 Z1\n$IF P1 == 1\nN20 M30\n$ENDIF\nN30 G74 X1\nN40 M30\n"
    program = read(text)
    assert isinstance(program.blocks[-1], HomingBlock) and program.end.line == 3


def test_explain_says_what_it_did_not_follow(portal):
    report = explain_machine(portal, read(REPORTED))
    rows = {row["name"]: row["homed"] for row in report["axes"]}
    assert rows["X"] == "line 1 (N10), step 1" and rows["Y"] == "line 1 (N10), step 2"
    for name in ("Z", "A", "S"):
        assert rows[name] == "not known: the program is not followed past line 6: `N45 LL X20`"
    assert rows["B"].startswith("not needed")
    assert report["program"]["unfollowed"] == {
        "line": 6,
        "text": "N45 LL X20",
        "reason": "LL X20: a subroutine call is not followed",
    }


def test_the_dry_run_stops_following_where_the_reader_stops(portal):
    text = "N10 G74 Z1\nN20 LL SUB\nN30 G01 G90 X10 F500\nN40 G74 X1\nN50 M30\n"
    run = dry_run(portal, text)
    assert [b.outcome for b in run.blocks] == ["done", "not_simulated", "not_simulated", "not_simulated"]
    assert run.blocks[2].note == "not simulated: the run stops following the program at line 2"
    assert run.axes["Z"].outcome == "homed"
    assert run.axes["X"].outcome == "not_simulated"  # not "not run": nothing failed
    assert run.axes["A"].outcome == "not_simulated"  # the subroutine may command it
    (note,) = [w for w in run.warnings if w["line"] == 2]
    assert note["message"].startswith("the run stops following the program here (LL SUB:")
    assert not [w for w in run.warnings if w["code"] == "LIS606"]
    # lint agrees: no finding claims X unhomed at line 3
    assert codes(portal, text) == []


def test_the_dry_run_stops_at_a_computed_position(portal):
    text = "N10 G74 Z1\nN20 G01 G90 Z[P1] F500\nN30 G01 X10\n"
    run = dry_run(portal, text)
    assert [b.outcome for b in run.blocks] == ["done", "not_simulated", "not_simulated"]
    assert run.blocks[1].axes == ["Z"]
    assert run.axes["X"].outcome == "not_simulated" and run.axes["A"].outcome == "not_commanded"
    # a call after the place the run stops may command any axis: none is "not commanded" then
    called = dry_run(portal, text + "N40 LL SUB\n")
    assert called.axes["A"].outcome == "not_simulated" and called.axes["Z"].outcome == "homed"


# -- properties ------------------------------------------------------------------------------------------

BLANKS = st.sampled_from(["", " ", "  ", "\t"])


def _joined(parts: list[str], blanks: list[str]) -> str:
    return "".join(part + blank for part, blank in zip(parts, blanks, strict=False)) + parts[-1]


OPERANDS = st.one_of(
    st.integers(0, 999).map(str),
    st.sampled_from(["0.5", "12.25", ".5", "3."]),
    st.integers(1, 99).map(lambda n: f"P{n}"),
    st.integers(1, 99).map(lambda n: f"PP{n}"),
    st.sampled_from(["V.P.NAME", "V.L.ARR[2]", "V.G.OFFSET", "V.CYC.DEPTH", "V.A.ABS.X", '"STRING1"', "R1"]),
)
OPERATORS = st.sampled_from(["+", "-", "*", "/", "**", " MOD ", "==", "<", ">=", "&", "|"])
FUNCTIONS = st.sampled_from(["SIN", "COS", "ABS", "SQRT", "SQR", "DEXP", "EXP", "LN", "INT"])


def _expressions(inner):
    binary = st.tuples(inner, OPERATORS, inner, BLANKS, BLANKS).map(
        lambda t: f"{t[0]}{t[3]}{t[1]}{t[4]}{t[2]}"
    )
    bracketed = st.tuples(inner, BLANKS).map(lambda t: f"[{t[1]}{t[0]}{t[1]}]")
    function = st.tuples(FUNCTIONS, BLANKS, inner).map(lambda t: f"{t[0]}{t[1]}[{t[2]}]")
    negated = inner.map(lambda e: f"-{e}")
    return st.one_of(binary, bracketed, function, negated)


EXPRESSIONS = st.recursive(OPERANDS, _expressions, max_leaves=8)
# Blocks of the grammar: each is ISG syntax the decoder reads.
BLOCKS = st.one_of(
    st.tuples(st.integers(1, 99), EXPRESSIONS, BLANKS).map(lambda t: f"P{t[0]}{t[2]}={t[2]}{t[1]}"),
    st.tuples(st.sampled_from(["V.P.NAME", "V.L.X[3]", "PP7", "P[P1+5]"]), EXPRESSIONS).map(
        lambda t: f"{t[0]} = {t[1]}"
    ),
    st.tuples(st.sampled_from("XYZA"), EXPRESSIONS).map(lambda t: f"G01 {t[0]}[{t[1]}] F100"),
    st.tuples(st.sampled_from("XYZA"), EXPRESSIONS).map(lambda t: f"G74 {t[0]}[{t[1]}]"),
    st.tuples(st.sampled_from("XYZA"), st.integers(1, 99), EXPRESSIONS).map(
        lambda t: (
            f"G01 {t[0]} P{t[1]}*{t[2]} F100" if not t[2].startswith("-") else f"G01 {t[0]}[{t[2]}] F100"
        )
    ),
)


@settings(max_examples=examples(200), deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(BLOCKS, min_size=1, max_size=6))
def test_well_formed_expressions_never_give_lis601(blocks):
    text = "".join(f"N{10 * (i + 1)} {block}\n" for i, block in enumerate(blocks))
    program = read(text)
    assert program.problems == [], (text, [(p.at.line, p.message) for p in program.problems])


NOISE = st.text(alphabet='[]()P=+-*/ X0123456789."VLG74$#;,NM%', max_size=60)


@settings(max_examples=examples(200), deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(NOISE, max_size=8))
def test_random_bracket_and_assignment_text_never_crashes(lines):
    text = "\n".join(lines)
    program = read(text)
    for at in [p.at for p in program.problems] + [b.at for b in program.blocks]:
        assert 1 <= at.line <= max(1, len(lines))
        line = lines[at.line - 1] if lines else ""
        assert 1 <= at.column <= len(line) + 1
        assert at.end_column is None or at.column <= at.end_column <= len(line) + 1


# Blocks a homing program may hold, some of which the reader does not follow.
PROGRAM_BLOCKS = st.sampled_from(
    [
        "G74 X1",
        "G74 Y1 Z2",
        "G74 Z[P1]",
        "G74 A1",
        "G01 G90 X10 F500",
        "G01 G90 Y10 F500",
        "G01 G90 Z10 F500",
        "G00 G91 A5",
        "G01 G90 Z[P2] F500",
        "P1 = 2",
        "LL SUB",
        '"MACRO"',
        "$IF P1 == 1",
        "$ENDIF",
        "$FOR P3 = 1,2,1",
        "$ENDFOR",
        "M[P4]",
    ]
)


def _line_of(homed_text: str) -> int | None:
    """The line an explain `homed` cell says the axis is (or perhaps is) homed at."""
    match = re.match(r"(?:perhaps: )?line (\d+)", homed_text)
    return int(match.group(1)) if match else None


@settings(max_examples=examples(150), deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(PROGRAM_BLOCKS, min_size=1, max_size=10))
def test_findings_explain_and_dry_run_never_contradict_each_other(portal, blocks):
    text = "".join(f"N{10 * (i + 1)} {block}\n" for i, block in enumerate(blocks)) + "M30\n"
    program = read(text)
    found = check_program(program, portal)
    assert "LIS601" not in {d.code for d in found}, text
    unhomed = {(d.line, d.message.split(" ", 1)[0]) for d in found if d.code == "LIS606"}
    # explain never says an axis is (or may be) homed before a line where LIS606 says it is not
    report = explain_machine(portal, program)
    rows = {row["name"]: row["homed"] for row in report["axes"]}
    for line, name in unhomed:
        homed_at = _line_of(rows[name])
        assert homed_at is None or homed_at > line, (text, line, name, rows[name])
    # every LIS606 the dry-run gives, lint gives too; and the run never simulates past what it does not follow
    run = run_machine(portal, program, parse_machine_scenario({}, "scenario"))
    for warning in run.warnings:
        if warning["code"] == "LIS606":
            name = warning["message"].split(" moves ", 1)[1].split(" ", 1)[0]
            assert (warning["line"], name) in unhomed, (text, warning)
    opaque = next((i for i, b in enumerate(program.blocks) if isinstance(b, SkippedBlock) and b.opaque), None)
    if opaque is not None:
        assert all(b.outcome == "not_simulated" for b in run.blocks[opaque:]), text

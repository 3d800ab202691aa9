"""The homing program reader: blocks, modal state, positions, and defects as problems (never a crash)."""

from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st

from achslint.machine.model import HomingBlock, Location, MoveBlock, SkippedBlock
from achslint.machine.program import read_program

from .conftest import examples

MANUAL = b"""%RPF.NC
N10 G74 Z1 (optional: move Z to safety height)
N15 G01 G90 Z200 F500
N20 G74 X1 Y1 A2 B2 S3
N30 G01 X0 Y20 Z0 A90 F1000
N40 SPOS0 S500
N50 M30
"""


def kinds(program):
    return [type(block).__name__ for block in program.blocks]


def messages(program):
    return [(p.at.line, p.at.column, p.message) for p in program.problems]


def test_the_manuals_program_block_by_block():
    program = read_program(MANUAL, "rfp.nc")
    assert kinds(program) == ["HomingBlock", "MoveBlock", "HomingBlock", "MoveBlock", "SkippedBlock"]
    assert program.problems == []
    z, move, xy, home, spindle = program.blocks
    assert isinstance(z, HomingBlock) and z.number == 10
    assert [(w.name, w.value) for w in z.words] == [("Z", 1.0)]
    # `N10 G74 Z1`: the block starts at N (column 1), Z1 takes columns 9-10
    assert z.at == Location("rfp.nc", 2, 1, 47)
    assert z.words[0].at == Location("rfp.nc", 2, 9, 11)
    assert isinstance(move, MoveBlock)
    assert (move.rapid, move.absolute, move.feed_mm_min) == (False, True, 500.0)
    assert [(w.name, w.value) for w in move.targets] == [("Z", 200.0)]
    assert isinstance(xy, HomingBlock)
    assert [(n, [w.name for w in words]) for n, words in xy.groups()] == [
        (1, ["X", "Y"]),
        (2, ["A", "B"]),
        (3, ["S"]),
    ]
    # G01 stays in force; the new F replaces 500
    assert isinstance(home, MoveBlock) and home.feed_mm_min == 1000.0 and not home.rapid
    assert {w.name: w.value for w in home.targets} == {"X": 0.0, "Y": 20.0, "Z": 0.0, "A": 90.0}
    assert isinstance(spindle, SkippedBlock) and "S500" in spindle.reason
    assert program.end == Location("rfp.nc", 7, 5, 8)


def test_modal_state_carries_over_and_g91_is_incremental():
    program = read_program(b"N1 G00 G91 X10\nN2 Y-5.5\nN3 G01 F300 G90 Z1\nN4 X2\n", "p.nc")
    first, second, third, fourth = program.blocks
    assert (first.rapid, first.absolute, first.feed_mm_min) == (True, False, None)
    assert (second.rapid, second.absolute) == (True, False)
    assert second.targets[0].value == -5.5
    assert (third.rapid, third.absolute, third.feed_mm_min) == (False, True, 300.0)
    assert (fourth.rapid, fourth.absolute, fourth.feed_mm_min) == (False, True, 300.0)
    assert program.problems == []


def test_extended_axis_names_with_equals():
    program = read_program(b"G74 Y2=1 S1=2\n", "p.nc")
    assert [(w.name, w.value) for w in program.blocks[0].words] == [("Y2", 1.0), ("S1", 2.0)]


def test_comments_and_blank_lines_make_no_block():
    program = read_program(b"%rfp\n\n( a comment )\n; another\n   \n(a) ; b\n", "p.nc")
    assert program.blocks == [] and program.problems == []


def test_a_position_before_any_motion_mode_is_not_guessed():
    program = read_program(b"X10\n", "p.nc")
    assert kinds(program) == ["SkippedBlock"]
    assert "G00 or G01" in program.blocks[0].reason


def test_blocks_after_the_program_end_are_not_read():
    program = read_program(b"G74 X1\nM30\nG74 Y1\n", "p.nc")
    assert kinds(program) == ["HomingBlock", "SkippedBlock"]
    assert program.end.line == 2


def test_a_comment_left_open_runs_to_the_end_of_its_block():
    # The ISG decoder ends a comment at the end of the block: `(` without `)` is no defect.
    program = read_program(b"N10 G74 Z1 (home the quill\nN20 G74 X1 (then ( Y2 as well\nN30 G74 Y2\n", "p.nc")
    assert messages(program) == []
    assert [[w.name for w in block.words] for block in program.blocks] == [["Z"], ["X"], ["Y"]]


def test_g74_without_axes():
    program = read_program(b"N20 G74 (nothing)\n", "p.nc")
    assert [m[2].split(":")[0] for m in messages(program)] == ["G74 names no axis to home"]
    assert program.blocks[0].words == ()


def test_bad_sequence_numbers_each_named_at_their_column():
    program = read_program(b"G74 X0 Y-1 Z1.5 A99999999999 B+2 C40000\n", "p.nc")
    found = [(column, message.split(":")[0]) for _, column, message in messages(program)]
    assert found == [
        (5, "G74 X0"),
        (8, "G74 Y-1"),
        (12, "G74 Z1.5"),
        (17, "G74 A99999999999"),
        (34, "G74 C40000"),
    ]
    # only B+2 is a usable order
    assert [(w.name, w.value) for w in program.blocks[0].words] == [("B", 2.0)]


def test_words_that_cannot_be_read():
    program = read_program(b"G74 X1 Y\nG01 X1 @ F10\nN1.5 G01 X2 F10\n", "p.nc")
    assert [(line, column) for line, column, _ in messages(program)] == [(2 - 1, 8), (2, 8), (3, 1)]
    assert "has no number" in program.problems[0].message
    assert "not an NC word" in program.problems[1].message
    assert "not a block number" in program.problems[2].message
    assert kinds(program) == ["SkippedBlock", "SkippedBlock", "MoveBlock"]


def test_g01_without_feed_and_a_zero_feed():
    program = read_program(b"G01 X1\nG01 X2 F0\n", "p.nc")
    assert [m[2] for m in messages(program)] == [
        "G01 without a feed rate: program F (mm/min)",
        "F0: a feed rate must be above 0 mm/min",
        "G01 without a feed rate: program F (mm/min)",
    ]


def test_a_binary_file_is_one_problem():
    program = read_program(b"\x00\x01\x02G74", "p.nc")
    assert program.blocks == []
    assert len(program.problems) == 1 and "not an NC program as text" in program.problems[0].message


def test_huge_numbers_are_problems_not_crashes():
    program = read_program(b"G01 X" + b"9" * 5000 + b" F1\nG74 Y" + b"9" * 5000 + b"\n", "p.nc")
    assert [line for line, _, _ in messages(program)] == [1, 2]


def check_positions(program, lines: list[str]) -> None:
    """Every location lies on its line: the reader never points outside the text."""
    places = [p.at for p in program.problems] + [b.at for b in program.blocks]
    places += [w.at for b in program.blocks if isinstance(b, HomingBlock) for w in b.words]
    places += [w.at for b in program.blocks if isinstance(b, MoveBlock) for w in b.targets]
    for at in places:
        assert 1 <= at.line <= max(1, len(lines))
        assert 1 <= at.column <= len(lines[at.line - 1]) + 1 if lines else at.column == 1
        assert at.end_column is None or at.end_column >= at.column


@settings(max_examples=examples(50), deadline=None)
@given(st.binary(max_size=300))
def test_random_bytes_never_crash(data):
    program = read_program(data, "random.nc")
    text = data.decode("latin-1")
    check_positions(program, text.replace("\r\n", "\n").replace("\r", "\n").split("\n"))


WORDS = st.sampled_from(
    ["N10", "G74", "G01", "G00", "G90", "G91", "X1", "Y-2", "Z1.5", "A0", "S3", "F500", "F0", "M30", "M02",
     "(", ")", ";", "Y2=1", "X", "%", "/", "#", "G17", "M3", "T1", "99999999999999999999", "Q1"]
)  # fmt: skip
LINES = st.lists(st.lists(WORDS, max_size=8).map(" ".join), max_size=12).map("\n".join)


@settings(max_examples=examples(50), deadline=None)
@given(LINES)
def test_generated_programs_never_crash_and_keep_their_places(text):
    program = read_program(text.encode(), "gen.nc")
    check_positions(program, text.split("\n"))
    for block in program.blocks:
        if isinstance(block, HomingBlock):
            assert all(w.value >= 1 and w.value == int(w.value) for w in block.words)

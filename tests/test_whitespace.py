"""Whitespace is the blank and the tab, and line breaks are CR, LF and CRLF — in fmt, the parser and the fixer.

Everything else (no-break space, \\x0b, \\x0c, \\x1c-\\x1f, U+0085, U+2028) is content: the
CNC reads it as part of a name, value or comment, so fmt must leave it where it is.
"""

from __future__ import annotations

import re

from hypothesis import given, settings
from hypothesis import strategies as st

from achslint.core.decode import decode
from achslint.fmt import format_bytes, unified_diff
from achslint.linting.fixer import fix_bytes
from achslint.linting.linter import lint_file
from achslint.syntax.parser import parse_text, split_lines

from .conftest import examples

OTHER_SPACES = ["\xa0", "\x0b", "\x0c", "\x1c", "\x1d", "\x1e", "\x1f", "\x85", "\u2028", "\u2029", "\u3000"]


def fields(line: str) -> list[str]:
    """What a line says, with blanks and tabs as the only separators."""
    return [part for part in re.split("[ \t]+", line) if part]


def test_no_break_space_after_a_string_is_kept_and_formatting_is_idempotent():
    # Why 3: `"a b"\xa0` lost its NBSP, and a second run changed the file again.
    data = 'kopf.log_achs_name "a b"\xa0\nEnde\n'.encode("latin-1")
    once, _ = format_bytes(data)
    assert b'"a b"\xa0\n' in once
    assert format_bytes(once) == (once, False)


def test_a_form_feed_after_a_number_stays_an_error():
    # Why 3: `1\x0c` is not a number for the CNC; stripping the form feed made it a valid `1`.
    data = b"kopf.achs_nr 1\x0c\nEnde\n"
    formatted, _ = format_bytes(data)
    assert b"1\x0c\n" in formatted
    assert [d.code for d in lint_file(formatted, "a.lis").diagnostics] == [
        d.code for d in lint_file(data, "a.lis").diagnostics
    ]


def test_a_cr_line_followed_by_a_blank_only_lf_line_is_not_merged():
    # Why 4: the CR and the LF of the emptied line became one CRLF; a line was lost.
    data = b"kopf.achs_nr 1\r  \nkenngr.achs_typ 1\nEnde\n"
    formatted, _ = format_bytes(data)
    assert split_lines(formatted.decode(), keepends=True)[:2] == ["kopf.achs_nr     1\r", "  \n"]
    assert len(parse_text(formatted.decode()).lines) == len(parse_text(data.decode()).lines)


def test_the_parser_counts_lines_only_at_cr_and_lf():
    text = "a 1\x0bb\x0c\x1c\x85\u2028x\r\ny 2\rz 3\n"
    assert split_lines(text) == ["a 1\x0bb\x0c\x1c\x85\u2028x", "y 2", "z 3"]
    assert [line.number for line in parse_text(text).lines] == [1, 2, 3, 4]
    assert lint_file(b"a\x0b 1\nkenngr.ref_ricth 1\nEnde\n", "a.lis").diagnostics[-1].line == 2


def test_the_fixer_edits_names_and_keeps_other_spaces_around_them():
    data = "kenngr.ref_ricth 1 (\xa0note\x0c \nkenngr.homing_type\tTORQ (\x85\nEnde\n".encode("latin-1")
    fixed = fix_bytes(data, "a.lis", unsafe=True).data  # ref_richt 1 changes behaviour: an unsafe fix
    assert fixed == "kenngr.ref_richt 1 (\xa0note\x0c \nkenngr.homing.homing_type\tTORQ (\x85\nEnde\n".encode(
        "latin-1"
    )


def test_diff_marks_a_missing_final_line_break():
    diff = unified_diff(b"a 1\nEnde", b"a  1\nEnde\n", "x.lis")
    assert diff.endswith("-Ende\n\\ No newline at end of file\n+a  1\n+Ende\n")
    assert unified_diff(b"a 1\n", b"a  1", "x.lis").endswith("+a  1\n\\ No newline at end of file\n")


LINE_BREAKS = st.sampled_from(["\n", "\r\n", "\r"])
SPACES = st.sampled_from([" ", "\t", *OTHER_SPACES])
WORDS = st.sampled_from(
    [
        "kopf.achs_nr",
        "kopf.log_achs_name",
        "getriebe[0].vb_reflow",
        "Ende",
        "1",
        "0x10",
        '"a b"',
        "X_Achse",
        "( note",
        "# c",
        "µ",
        "bad[x]",
        "é",
    ]
)
LINE = st.lists(st.one_of(WORDS, SPACES), max_size=8).map("".join)
# Blank-only lines (blanks, tabs and the other spaces) between lines with any mix of breaks.
TEXT = st.lists(
    st.tuples(st.one_of(LINE, st.lists(SPACES, max_size=3).map("".join)), LINE_BREAKS), max_size=12
).map(lambda rows: "".join(body + brk for body, brk in rows))


@settings(max_examples=examples(400), deadline=None)
@given(TEXT, st.sampled_from(["utf-8", "latin-1"]))
def test_fmt_changes_blanks_and_tabs_only_and_keeps_every_line_break(text, encoding):
    data = text.encode(encoding, "ignore")
    formatted, _ = format_bytes(data)
    assert format_bytes(formatted) == (formatted, False)  # idempotent
    before = split_lines(decode(data).text, keepends=True)
    after = split_lines(decode(formatted).text, keepends=True)
    end = parse_text(decode(data).text).end_index  # the end marker as the parser reads it
    # Lines are only ever dropped at the end, after `Ende`, and only when blank.
    assert len(after) <= len(before)
    for dropped in before[len(after) :]:
        assert end is not None and not dropped.rstrip("\r\n").strip(" \t")
    for old, new in zip(before, after, strict=False):
        assert fields(old.rstrip("\r\n")) == fields(new.rstrip("\r\n"))
        old_break, new_break = old[len(old.rstrip("\r\n")) :], new[len(new.rstrip("\r\n")) :]
        assert new_break == old_break or (not old_break and new is after[-1])

"""`fmt.LiveFormat`: formatting a list edited over and over (the language server) gives `achslint fmt`'s
text byte for byte, after every edit, while reading only the lines an edit changed."""

from __future__ import annotations

import random

import pytest

from achslint import fmt
from achslint.core.decode import decode
from achslint.fmt import FmtOptions, LiveFormat, format_bytes, format_file
from achslint.syntax import parser as syntax

from .conftest import FIXTURES, examples
from .fixture_lists import distinct_lists

FIXTURE_LISTS = distinct_lists()  # a copy of a list (same bytes and name) would repeat the same test
PATHS = [
    "kopf.achs_nr",
    "getriebe[0].vb_reflow",
    "kenngr.homing.homing_type",
    "kopf.log_achs_name",
    "antr.fixed_stop.drive_ident[0].rd_ident",
    "lslj.kenngr.swe_pos",
    "bad[i].line",
]
VALUES = ["1", "20000", "CNC_CONTROLLED", "X_Achse", "-5", "0x1F", '"text"', "1.5", "P-AXIS-00212.0"]
GAPS = [" ", "  ", "\t", "    ", "\t\t", "        ", " \t", "              "]
COMMENTS = ["", "( comment", "# note", "(x", "  ( spaced", "/* c"]
BREAKS = ["\n", "\n", "\r\n", "\r"]
OPTIONS = [
    FmtOptions(),
    FmtOptions(align_values="right"),
    FmtOptions(align_values="left"),
    FmtOptions(comment_column=40),
    FmtOptions(value_column=30),
    FmtOptions(value_column=50, align_values="right"),
]


def random_line(rng: random.Random) -> str:
    if rng.random() < 0.12:
        return rng.choice(["", "   ", "\t", "# a comment  ", "Ende", " Ende  ", "Ende (x"]) + rng.choice(
            BREAKS
        )
    indent = rng.choice(["", "", "", "", " ", "\t"])
    parts = [rng.choice(PATHS), rng.choice(GAPS), rng.choice(VALUES), rng.choice(GAPS), rng.choice(COMMENTS)]
    return indent + "".join(parts) + rng.choice(BREAKS)


def edited(rng: random.Random, lines: list[str]) -> list[str]:
    """The lines after one edit an editor could make: a character typed or deleted, lines inserted, removed
    or replaced, a line break removed (two lines joined) or the end marker added."""
    lines = list(lines)
    where = rng.randrange(len(lines) + 1)
    at = min(where, len(lines) - 1)
    choice = rng.random()
    if choice < 0.35 and lines:
        line = lines[at]
        column = rng.randrange(len(line) + 1)
        typed = rng.choice([" ", "\t", "x", "1", "", "  ", "("])
        lines[at] = line[:column] + typed + line[column + rng.randrange(2) :]
    elif choice < 0.55:
        lines[where:where] = [random_line(rng) for _ in range(rng.randrange(1, 5))]
    elif choice < 0.7 and lines:
        del lines[at : at + rng.randrange(1, 4)]
    elif choice < 0.8 and lines:
        lines[at] = random_line(rng)
    elif choice < 0.88 and lines:
        lines[at] = lines[at].rstrip("\r\n")
    else:
        lines.append(rng.choice(["Ende\n", "Ende", "\n", "  \n", "\r\n"]))
    return lines


def applied(raw: list[str], blocks: list[fmt.Block]) -> str:
    lines = list(raw)
    for first, stop, text in reversed(blocks):
        lines[first:stop] = [text]
    return "".join(lines)


def check(live: LiveFormat, text: str, full: bool = True) -> None:
    """The live formatting of `text` is fmt's, as text and as the changes to its lines."""
    raw = syntax.split_lines(text, keepends=True)
    if not live.update(raw, full=full):
        assert not full
        assert live.update(raw)  # formatting every line again is left to a call that allows it
    expected = format_file(syntax.parse_text(text), live.options)
    assert live.text() == expected
    assert applied(raw, live.changes()) == expected


@pytest.mark.parametrize("path", FIXTURE_LISTS, ids=lambda path: str(path.relative_to(FIXTURES)))
def test_every_fixture_list_as_fmt_formats_it(path):
    data = path.read_bytes()
    try:
        source = decode(data)
    except Exception:
        return  # fmt refuses it (UTF-16 ...); the editor shows it as a diagnostic instead
    live = LiveFormat()
    check(live, source.text)
    assert source.encode(live.text()) == format_bytes(data)[0]
    # and again after edits of it
    rng = random.Random(path.name)
    lines = syntax.split_lines(source.text, keepends=True)
    for _ in range(5):
        lines = edited(rng, lines)
        check(live, "".join(lines))


@pytest.mark.parametrize("seed", range(examples(60)))
def test_random_edit_sequences_stay_fmt(seed):
    rng = random.Random(seed)
    lines = [random_line(rng) for _ in range(rng.randrange(1, 40))]
    live = LiveFormat(rng.choice(OPTIONS))
    for _ in range(40):
        check(live, "".join(lines), full=rng.random() < 0.5)
        lines = edited(rng, lines)


def large_list(rng: random.Random, count: int) -> list[str]:
    """A long list in one layout: paths padded to a value column, comments in a column, a block right-aligned."""
    lines = ["# a long list\n"]
    for number in range(count):
        path = f"{rng.choice(PATHS[:6])}{number}"
        value = rng.choice(VALUES[:6])
        if 1000 <= number < 1010:  # a block of right-aligned values
            lines.append(f"{path.ljust(40)}{value.rjust(20)}\n")
        else:
            lines.append(f"{path.ljust(48)}{value.ljust(20)}( P-AXIS-{number:05d}\n")
    return [*lines, "Ende\n"]


# What `str.splitlines` ends a line at besides CR, LF and CRLF (where `syntax.split_lines` does not).
OTHER_BREAKS = "\x0b\x0c\x1c\x1d\x1e\x85\u2028\u2029"


def split_long(text: str) -> list[str]:
    """`syntax.split_lines(text, keepends=True)` for a long text: the same lines from `str.splitlines` (a
    seventh of the time on 5,000 lines) when the text holds no other character that splits there."""
    if any(character in text for character in OTHER_BREAKS):
        return syntax.split_lines(text, keepends=True)
    return text.splitlines(keepends=True)


def test_edits_of_a_large_list_read_only_the_edited_lines(monkeypatch):
    rng = random.Random(28)
    lines = large_list(rng, 5000)
    live = LiveFormat()
    check(live, "".join(lines))
    whole: list[str] = []  # every line formatted again: only when a decision about the whole file changes
    for name in ("_vote_all", "_mark_all"):
        original = getattr(LiveFormat, name)

        def counted(self, *args, original=original, name=name):
            whole.append(name)
            return original(self, *args)

        monkeypatch.setattr(LiveFormat, name, counted)
    # Compared with a whole format_file every 50 edits and after the last (each parses all 5,000 lines
    # again, most of the test's time); the random edit sequences above compare after every edit. The lines
    # each edit leaves come from split_long, compared with split_lines' at those steps too.
    for step in range(1, 201):
        lines = edited(rng, lines)
        text = "".join(lines)
        raw = split_long(text)
        assert live.update(raw, full=False), step
        if step % 50 == 0:
            assert raw == syntax.split_lines(text, keepends=True)
            check(live, text)
    assert whole == []


def test_a_changed_decision_formats_every_line_again():
    text = "a  1\nb  2\nccc 3\nEnde\n"
    live = LiveFormat()
    check(live, text)
    # two of three values now start in column 5: the main alignment moves, every line follows
    changed = "a   1\nb   2\nccc 3\nEnde\n"
    assert not live.update(syntax.split_lines(changed, keepends=True), full=False)
    check(live, changed)
    assert live.changes() == []  # formatted already


def test_changes_are_the_lines_fmt_rewrites():
    text = "a 1\nbb    2\nccc  3\nEnde\n\n  \n"
    live = LiveFormat()
    check(live, text)
    # values two blanks after the longest path: the third line stays; the blank lines after the end marker
    # go (replaced by nothing)
    assert live.changes() == [(0, 2, "a    1\nbb   2\n"), (4, 6, "")]
    unterminated = LiveFormat()
    check(unterminated, "a  1\nEnde")
    assert unterminated.changes() == [(1, 2, "Ende\n")]  # the end marker gets the file's line break


def spaced(start: int, stop: int, tabs: bool) -> str:
    """Whitespace from column `start` to column `stop` (at least one blank): tab stops every 8 columns first,
    if `tabs`."""
    gap = ""
    while tabs and (start // 8 + 1) * 8 <= stop:
        gap, start = gap + "\t", (start // 8 + 1) * 8
    return gap + " " * (stop - start) if gap or stop > start else " "


def layout_line(rng: random.Random, column: int, comments: int, tabs: float = 0.05) -> str:
    """A value line in a layout (values from `column`, comments from `comments`), or nearly: now and then its
    comment one blank after the value or off the column, blanks at its end, or its value ending in the column
    instead. Its gaps are tabs as far as they go with probability `tabs`."""
    path, value = rng.choice(PATHS), rng.choice(VALUES)
    if rng.random() < 0.2:  # right-aligned: the value ends in the column
        text = path + spaced(len(path), column + 16 - len(value), rng.random() < tabs) + value
    else:
        text = path + spaced(len(path), column, rng.random() < tabs) + value
    if rng.random() < 0.7:
        comment = rng.choice(["( comment", "(x", "# note", "/* c", "( P-AXIS-00016 : a comment"])
        where = rng.choice([comments, comments, comments, len(text) + 1, len(text) + 2, comments + 3])
        text += spaced(len(text.expandtabs(8)), where, rng.random() < tabs) + comment
    text += rng.choice(["", "", "", "", " ", "  ", "\t"])
    return text + rng.choice(BREAKS[:3])


def layout_list(rng: random.Random, count: int) -> list[str]:
    column, comments = rng.choice([(40, 60), (48, 68), (24, 40), (16, 24)])
    tabs = rng.choice([0.0, 0.05, 0.8])  # (0.8: a list separated by tabs, blanks here and there)
    lines = [
        layout_line(rng, column, comments, tabs) if rng.random() < 0.85 else random_line(rng)
        for _ in range(count)
    ]
    return [*lines, "Ende\n"] if rng.random() < 0.7 else lines


@pytest.mark.parametrize("seed", range(examples(40)))
def test_lists_in_a_layout_stay_fmt(seed):
    """Most lines of such a list already stand where the layout wants them: LiveFormat finds what becomes of
    them without working them through as `format_file` does (`_facts_of`); the text is `format_file`'s all
    the same, before and after edits."""
    rng = random.Random(seed)
    lines = layout_list(rng, rng.randrange(5, 80))
    live = LiveFormat(rng.choice([FmtOptions(), *OPTIONS]))  # (the list's own layout more often)
    for _ in range(15):
        check(live, "".join(lines), full=rng.random() < 0.5)
        lines = edited(rng, lines)
        if rng.random() < 0.3:
            at = rng.randrange(len(lines) + 1)
            lines[at:at] = [layout_line(rng, 40, 60)]


@pytest.mark.parametrize("seed", range(examples(20)))
def test_facts_of_a_line_are_what_its_row_works_out(seed):
    """What LiveFormat keeps of a value line is what `_Row` (`format_file`'s way) works out for it, and a line
    it finds plain stays as it is (but for blanks at its end) when its value and comment stay where they are."""
    rng = random.Random(seed)
    live = LiveFormat()
    for _ in range(300):
        text = layout_line(rng, 40, 60) if rng.random() < 0.5 else random_line(rng)
        body = text.rstrip("\r\n")
        line = syntax.parse_text(body).lines[0]
        if not fmt._aligns(line):
            continue
        row = fmt._row(line)
        found = live._facts_of(line, body)
        assert found[0] == (None if row.indent else row.alignments()), body
        assert found[1:4] == (row.value_start, row.extent_end, fmt._width(row)), body
        assert found[4] == ("\t" in row.sep if fmt._next_stop(row.path_end) <= row.value_start else None), (
            body
        )
        assert found[5] == fmt._mark(row), body
        assert found[7:] == (row.comment_start if row.free else -1, row.value_end), body
        if found[6] and not row.indent:
            placed = row.copy()
            left = fmt.Alignment("left", row.value_start)
            fmt._place_value(placed, left, {left}, tabs=False)
            fmt._place_comment(placed, found[7] if row.free else None, canonical=False, tabs=False)
            assert placed.body() == body.rstrip(" \t"), body
            assert (found[6] == 1) == (body == body.rstrip(" \t")), body


def test_a_list_in_its_layout_is_formatted_without_working_through_its_lines(monkeypatch):
    """The first formatting of a list works through `_Row` only the lines whose values move (what makes it
    take a tenth of a second for 50,000 lines in a layout rather than half a second)."""
    made: list[str | None] = []
    row = fmt._row

    def counted(line):
        made.append(line.path)
        return row(line)

    monkeypatch.setattr(fmt, "_row", counted)
    lines = large_list(random.Random(28), 5000)
    lines[10] = lines[10].rstrip("\n") + "  \n"  # blanks at its end: it only loses them
    live = LiveFormat()
    check(live, "".join(lines))
    changed = [index for first, stop, _ in live.changes() for index in range(first, stop)]
    assert changed[0] == 10 and live.formatted(10, 11) == [lines[10].rstrip(" \n") + "\n"]
    moved = {syntax.parse_text(lines[index]).lines[0].path for index in changed[1:]}
    assert 0 < len(moved) < 10  # (a few long paths in the right-aligned block)
    assert set(made) == moved

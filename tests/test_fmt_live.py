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

FIXTURE_LISTS = sorted(FIXTURES.rglob("*.lis"))
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
    # again, most of the test's time); the random edit sequences above compare after every edit.
    for step in range(1, 201):
        lines = edited(rng, lines)
        text = "".join(lines)
        assert live.update(syntax.split_lines(text, keepends=True), full=False), step
        if step % 50 == 0:
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

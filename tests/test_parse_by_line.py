"""`syntax.parse_text` parses only the lines it has not seen (`parser._LineParses`): the lines it gives are
those of a Lark parse of the whole text, field for field, whatever was parsed before."""

from __future__ import annotations

import random
from dataclasses import fields
from operator import attrgetter

import pytest

from achslint.syntax import parser as syntax

from .conftest import FIXTURES

PIECES = [
    "kopf.achs_nr",
    "getriebe[0].vb_reflow",
    "kenngr.homing.homing_type",
    "antr.fixed_stop.drive_ident[0].rd_ident",
    "Ende",
    "Ende(x",
    "End",
    "#TC_AXIS_DESC: x",
    "# note",
    "9bad",
    "a..b",
    "x[",
    "",
]
VALUES = ["1", "-5", "0x1F", "1.5", "2e3", "P-AXIS-00212.0", '"text"', '"open', '"a"b', "WORD", "µ"]
GAPS = ["", " ", "\t", "   ", " \t "]
TRAILERS = ["", "( comment", "# note", "x y z", "  ", "\t"]
BREAKS = ["\n", "\r\n", "\r"]


def random_text(rng: random.Random) -> str:
    lines = []
    for _ in range(rng.randrange(0, 25)):
        parts = [rng.choice(GAPS), rng.choice(PIECES)]
        if rng.random() < 0.8:
            parts += [rng.choice(GAPS[1:]), rng.choice(VALUES)]
        if rng.random() < 0.5:
            parts += [rng.choice(GAPS[1:]), rng.choice(TRAILERS)]
        lines.append("".join(parts) + rng.choice(BREAKS))
    text = "".join(lines)
    return text[:-1] if text and rng.random() < 0.3 else text  # sometimes no break at the end


# A line's fields as a tuple, as `dataclasses.astuple` gives them (every field is a string, a flag or a
# number) but deep-copies each one, most of these tests' time.
fields_of = attrgetter(*(field.name for field in fields(syntax.Line)))


def whole(text: str) -> list[tuple]:
    """The lines of one Lark parse of the whole text (as the parser gave them before the line cache)."""
    lines = syntax.parser().parse(text)
    return [(*fields_of(line)[:-1], number) for number, line in enumerate(lines, 1)]


@pytest.fixture
def fresh(monkeypatch):
    """An empty line cache and no recently parsed texts, for this test only."""
    monkeypatch.setattr(syntax, "_by_line", syntax._LineParses())
    monkeypatch.setattr(syntax, "_recent", syntax._RecentParses())


@pytest.mark.parametrize("seed", range(40))
def test_each_line_is_what_the_whole_parse_gives(seed, fresh):
    rng = random.Random(seed)
    for _ in range(6):  # the first with nothing seen, the next sharing lines with those before
        text = random_text(rng)
        assert [fields_of(line) for line in syntax.parse_text(text).lines] == whole(text), repr(text)


def test_every_fixture_list_parses_as_one_text(fresh):
    for path in sorted(FIXTURES.rglob("*.lis"))[:200]:
        text = path.read_bytes().decode("latin-1")
        assert [fields_of(line) for line in syntax.parse_text(text).lines] == whole(text), path


def test_only_new_lines_reach_lark_and_the_lines_are_new_objects(fresh, monkeypatch):
    first = "kopf.achs_nr 1\ngetriebe[0].vb_reflow 20000  ( speed\nEnde\n"
    one = syntax.parse_text(first)
    given: list[str] = []
    lark = syntax.parser()

    class Counting:
        def parse(self, text: str):
            given.append(text)
            return lark.parse(text)

    monkeypatch.setattr(syntax, "parser", Counting)
    again = syntax.parse_text(first.replace("1\n", "2\r\n", 1) + "kenngr.achs_typ 1")
    assert given == ["kopf.achs_nr 2\nkenngr.achs_typ 1"]  # the two lines not seen before, once each
    assert [line.newline for line in again.lines] == ["\r\n", "\n", "\n", ""]
    assert [line.number for line in again.lines] == [1, 2, 3, 4]
    assert again.lines[1] is not one.lines[1] and fields_of(again.lines[1]) == fields_of(one.lines[1])
    again.lines[1].value = "changed"  # the caller's to change: the next parse is not touched
    assert syntax.parse_text(first).lines[1].value == "20000"


def test_the_cache_is_bounded(fresh, monkeypatch):
    cache = syntax._by_line
    monkeypatch.setattr(cache, "count_limit", 10)
    monkeypatch.setattr(cache, "line_limit", 20)
    syntax.parse_text("".join(f"kopf.achs_nr {n}\n" for n in range(8)) + "x " * 20 + "\n")
    assert len(cache._kept) == 9  # eight numbered lines and the empty last one; the long line is not kept
    syntax.parse_text("".join(f"kenngr.p{n} 1\n" for n in range(5)))
    assert len(cache._kept) <= 10 and "kenngr.p4 1" in cache._kept  # full: the old ones were forgotten

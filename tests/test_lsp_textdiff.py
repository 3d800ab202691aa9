"""The line diff behind formatting and fix-all edits: always correct, minimal for the formatter's changes."""

from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st

from achslint.lsp.textdiff import changed_blocks

from .conftest import examples

# A few distinct lines and some repeated ones, so matching must cope with both.
LINE = st.sampled_from(["a\n", "b\n", "c\n", "kopf.achs_nr 1\n", "\n", "Ende\n"]) | st.text(
    "xyz", max_size=3
).map(lambda s: s + "\n")


def applied(old: list[str], new: list[str], blocks: list[tuple[int, int, int, int]]) -> list[str]:
    out, at = [], 0
    for i1, i2, j1, j2 in blocks:
        out += old[at:i1] + new[j1:j2]
        at = i2
    return out + old[at:]


def well_formed(blocks: list[tuple[int, int, int, int]]) -> bool:
    ends = [(0, 0)] + [(b[1], b[3]) for b in blocks]
    starts = [(b[0], b[2]) for b in blocks]
    in_order = all(s[0] >= e[0] and s[1] >= e[1] for s, e in zip(starts, ends, strict=False))
    return in_order and all(i1 < i2 or j1 < j2 for i1, i2, j1, j2 in blocks)


@st.composite
def edited(draw: st.DrawFn) -> tuple[list[str], list[str]]:
    old = draw(st.lists(LINE, max_size=30))
    new = list(old)
    for _ in range(draw(st.integers(0, 6))):
        at = draw(st.integers(0, len(new)))
        edit = draw(st.sampled_from(["replace", "insert", "delete", "move"]))
        if edit == "insert" or not new:
            new.insert(at, draw(LINE))
        elif edit == "replace" and at < len(new):
            new[at] = draw(LINE)
        elif edit == "delete" and at < len(new):
            del new[at]
        elif edit == "move" and at < len(new):
            new.insert(draw(st.integers(0, len(new) - 1)), new.pop(at))
    return old, new


@settings(max_examples=examples(1000, 40), deadline=None)
@given(edited())
def test_blocks_turn_old_into_new(pair: tuple[list[str], list[str]]) -> None:
    old, new = pair
    blocks = changed_blocks(old, new)
    assert applied(old, new, blocks) == new
    assert well_formed(blocks)
    assert (blocks == []) == (old == new)


@settings(max_examples=examples(300, 40), deadline=None)
@given(st.lists(st.tuples(LINE, st.booleans()), max_size=40))
def test_lines_changed_in_place_are_the_only_ones_edited(rows: list[tuple[str, bool]]) -> None:
    # What the formatter does: the same number of lines, some of them rewritten (into a new layout).
    old = [line for line, _ in rows]
    new = [f"  {line}" if change else line for line, change in rows]
    blocks = changed_blocks(old, new)
    edited_lines = {i for i1, i2, _, _ in blocks for i in range(i1, i2)}
    assert edited_lines == {i for i, (a, b) in enumerate(zip(old, new, strict=True)) if a != b}
    assert all(i2 - i1 == j2 - j1 for i1, i2, j1, j2 in blocks)


def test_a_removed_or_added_line_among_distinct_lines_is_one_block() -> None:
    old = [f"line {n}\n" for n in range(1000)]
    assert changed_blocks(old, old[:400] + old[401:]) == [(400, 401, 400, 400)]
    assert changed_blocks(old, [*old[:10], "new\n", *old[10:]]) == [(10, 10, 10, 11)]
    # Lines moved: the longest ordered run stays, the rest is edited.
    moved = old[:5] + old[6:900] + [old[5]] + old[900:]
    assert applied(old, moved, changed_blocks(old, moved)) == moved
    assert len(changed_blocks(old, moved)) == 2


def test_repeated_lines_and_the_ends() -> None:
    same = ["kopf.achs_nr 1\n"] * 500
    assert changed_blocks([*same, "Ende\n"], ["kopf.achs_nr 1\n", "Ende\n"]) == [(1, 500, 1, 1)]
    assert changed_blocks([], ["a\n"]) == [(0, 0, 0, 1)]
    assert changed_blocks(["a\n"], []) == [(0, 1, 0, 0)]
    assert changed_blocks(["a"], ["a\n"]) == [(0, 1, 0, 1)]

"""The fixer stays linear in the size of a list (issue 22: never hang): fixes are given the behaviour test
in groups within a fixed number of checks, and edits are applied in one pass."""

from __future__ import annotations

import random

from achslint.core.decode import decode
from achslint.core.diagnostics import Edit, Fix
from achslint.linting import fixer
from achslint.linting.fixer import MAX_CHECKS, apply_edits, fix_bytes

SAFE = b"kenngr.homing.homing_type CNC_CONROLLED\n"  # a typo fixed into a value the drive supports
RISKY = b"kenngr.homing.homing_type DRIVE_CONROLLED\n"  # fixed into one a conventional drive cannot run


def _counting_lints(monkeypatch) -> list[int]:
    calls: list[int] = []
    real = fixer.lint_file

    def counted(data, *args, **kwargs):
        calls.append(len(data))
        return real(data, *args, **kwargs)

    monkeypatch.setattr(fixer, "lint_file", counted)
    return calls


def test_thousands_of_risky_fixes_cost_a_bounded_number_of_lints(monkeypatch):
    """Before, every safe fix was checked with a lint of the whole list of its own: 1,000 fixes, 1,000
    lints (90 s). Now a round costs at most MAX_CHECKS lints, and nothing unchecked is applied as safe."""
    calls = _counting_lints(monkeypatch)
    data = b"kenngr.antr_typ 1\n" + RISKY * 300 + b"Ende\n"
    outcome = fix_bytes(data, "x.lis")
    assert outcome.data == data and outcome.fixed == 0
    assert len(calls) <= MAX_CHECKS + 1
    reasons = {d.fix.description.rsplit("(", 1)[-1] for d in outcome.result.diagnostics if d.fix}
    assert {d.fix.applicability for d in outcome.result.diagnostics if d.fix} == {"unsafe"}
    assert reasons == {
        "changes what the CNC does)",
        "not checked: too many fixes in one list, run --fix again or review them)",
    }


def test_safe_fixes_in_bulk_are_checked_together(monkeypatch):
    calls = _counting_lints(monkeypatch)
    data = b"kenngr.antr_typ 1\n" + SAFE * 500 + b"Ende\n"
    outcome = fix_bytes(data, "x.lis")
    assert outcome.fixed == 500 and b"CNC_CONROLLED" not in outcome.data
    assert len(calls) <= 4  # the lint, one group check, the lint of the fixed list, its group check


def test_one_risky_fix_among_safe_ones_is_found_by_halving():
    lines = [SAFE] * 20
    lines[13] = b"kenngr.ref_ricth 1\n"  # the fix would switch on ref_richt = 1, which the CNC now ignores
    data = b"kenngr.antr_typ 1\n" + b"".join(lines) + b"Ende\n"
    outcome = fix_bytes(data, "x.lis")
    fixed = outcome.data.split(b"\n")
    assert outcome.fixed == 19
    assert fixed[14] == b"kenngr.ref_ricth 1"  # line 15: the risky one stays as written
    assert fixed.count(b"kenngr.homing.homing_type CNC_CONTROLLED") == 19
    [left] = [d for d in outcome.result.diagnostics if d.fix]
    assert left.line == 15 and left.fix.applicability == "unsafe"


def test_many_edits_apply_in_one_pass_like_one_by_one():
    rng = random.Random(5)
    text = "".join(f"p{i} {rng.randint(0, 9)}\n" for i in range(3000))
    source = decode(text.encode())
    fixes = [
        Fix("safe", "x", (Edit(line, 1, line, 1 + rng.randint(1, 3), rng.choice(["", "q", "qq"])),))
        for line in rng.sample(range(1, 3001), 2000)
    ]
    fixes += fixes[:50]  # overlapping duplicates: skipped, left for the next round
    fixed, applied = apply_edits(source, fixes)
    assert applied == 2000
    expected = text.split("\n")
    for fix in fixes[:2000]:
        edit = fix.edits[0]
        line = expected[edit.line - 1]
        expected[edit.line - 1] = edit.content + line[edit.end_column - 1 :]
    assert fixed.text == "\n".join(expected)


def test_an_insertion_and_a_replacement_at_one_place_apply_in_text_order():
    """Found by review: a replacement taken before an insertion at its start duplicated text."""
    source = decode(b"kenngr.abc 1\nkenngr.xyz 2\n")
    replace_name = Fix("safe", "x", (Edit(2, 1, 2, 11, "kenngr.XYZ"),))
    insert_line = Fix("safe", "x", (Edit(2, 1, 2, 1, "# new\n"),))
    fixed, applied = apply_edits(source, [replace_name, insert_line])
    assert applied == 2
    assert fixed.text == "kenngr.abc 1\n# new\nkenngr.XYZ 2\n"
    overlapping = Fix("safe", "x", (Edit(2, 1, 2, 2, "K"),))
    _, applied = apply_edits(source, [insert_line, replace_name, overlapping])
    assert applied == 2  # the one-character replacement overlaps the name's

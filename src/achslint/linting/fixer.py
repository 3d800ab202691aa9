"""`lint --fix`: apply the fixes that rules attach to their diagnostics.

Fixes are edits on the decoded text (1-based line/column, end exclusive), plus
the removal of a UTF-8 byte-order mark. Only diagnostics that survived the
`noqa` suppressions carry fixes here, so a suppressed finding is never fixed.
Safe fixes are applied by default, unsafe ones only when asked. Fixing repeats
(lint, fix, lint again) until nothing fixable is left, so a second run finds
nothing to do; overlapping edits wait for the next round.

A fix a rule calls safe is applied as safe only when it keeps what the machine
does (ruff's meaning of safe): after it, the resolved axis (after the CNC's
corrections) is the same except for the parameter of the corrected finding, and
no finding appears that was not there before. A symbol typo fixed into a homing
type the drive does not support, or a misspelt name fixed into a parameter that
then takes effect with another value, fails that test and becomes unsafe. The
fixes of one round are tested together (all their parameters may change); a
group that fails is halved until the fixes that fail alone are found, within a
fixed number of checks, so the cost stays linear in the size of the list.
"""

from __future__ import annotations

import bisect
import itertools
from collections import Counter
from collections.abc import Iterable
from dataclasses import dataclass, replace

from ..core.decode import SourceText, decode
from ..core.diagnostics import Diagnostic, Fix
from ..syntax.parser import parse_text
from .linter import FileResult, FileSettings, lint_file

MAX_ROUNDS = 10


@dataclass
class FixOutcome:
    data: bytes  # the fixed bytes (the input when nothing changed)
    fixed: int  # number of diagnostics fixed
    result: FileResult  # diagnostics of the fixed bytes
    # (code, line, column) of the findings of the input whose fix its lint called safe and the behaviour test
    # refused (what a plain lint shows as unsafe)
    refused: frozenset[tuple[str, int, int]] = frozenset()


def _offsets(text: str) -> list[int]:
    """Character offset of the start of every line (as the parser numbers them)."""
    return parse_text(text).offsets()


def _overlaps(spans: list[tuple[int, int, str]], start: int, end: int) -> bool:
    """Whether [start, end) overlaps one of the sorted, disjoint `spans` (only the neighbours can)."""
    index = bisect.bisect_left(spans, (start, end), key=_order)
    before = spans[index - 1] if index else None
    after = spans[index] if index < len(spans) else None
    return bool(
        (before and before[0] < end and start < before[1]) or (after and after[0] < end and start < after[1])
    )


def _order(span: tuple[int, int, str]) -> tuple[int, int]:
    """Spans in text order; an insertion before a replacement that starts where it does."""
    return span[0], span[1]


def _overlap_each_other(ranges: list[tuple[int, int, str]]) -> bool:
    ordered = sorted(ranges, key=_order)
    return any(first[1] > second[0] for first, second in itertools.pairwise(ordered))


def apply_edits(source: SourceText, fixes: Iterable[Fix]) -> tuple[SourceText, int]:
    """Apply non-overlapping fixes; returns the new source and how many fixes went in."""
    text = source.text
    starts = _offsets(text)
    bom = source.bom
    spans: list[tuple[int, int, str]] = []  # kept in text order (`_order`): the overlap test bisects
    applied = 0
    for fix in fixes:
        if fix.remove_bom:
            if bom:
                bom = False
                applied += 1
            continue
        ranges = [
            (starts[e.line - 1] + e.column - 1, starts[e.end_line - 1] + e.end_column - 1, e.content)
            for e in fix.edits
        ]
        if any(_overlaps(spans, start, end) for start, end, _ in ranges) or _overlap_each_other(ranges):
            continue  # overlaps an edit already taken: next round
        for span in ranges:
            bisect.insort(spans, span, key=_order)
        applied += 1
    pieces, done = [], 0  # one pass over the text: a list with thousands of fixes stays linear
    for start, end, content in spans:
        pieces += [text[done:start], content]
        done = end
    pieces.append(text[done:])
    return SourceText("".join(pieces), source.encoding, bom), applied


def behaviour(data: bytes, name: str, defaults: bytes | None = None) -> dict[str, str]:
    """What the CNC ends up with: every parameter the list sets, with the value used after corrections
    (`defaults`: the default list loaded under it)."""
    from ..axis.resolved import resolve_bytes

    axis = resolve_bytes(data, name, defaults)
    return {path: repr(axis.get(path)) for path in axis.set_paths()}


def keeps_behaviour(
    data: bytes,
    name: str,
    settings: FileSettings | None,
    diagnostic: Diagnostic,
    before: FileResult,
    defaults: bytes | None = None,
) -> bool:
    """Whether `diagnostic`'s fix changes nothing but the corrected finding (see the module docstring)."""
    return _Check(data, name, settings, before, defaults).keeps([diagnostic])


# At most this many behaviour checks (each a lint of the whole list) per round: fixes are checked
# together, and a group that fails is halved, so a list whose fixes all keep behaviour costs one check
# and one with a few risky fixes a few dozen. Fixes left unchecked when the budget runs out are not
# applied as safe: a hostile list with thousands of risky fixes cannot make the fixer quadratic.
MAX_CHECKS = 24


class _Check:
    """The behaviour test of a list's fixes, against one lint and one resolved axis of the list (with the
    default list the CNC loads under it, as `achslint lint` lints it)."""

    def __init__(
        self,
        data: bytes,
        name: str,
        settings: FileSettings | None,
        before: FileResult,
        defaults: bytes | None = None,
    ) -> None:
        from ..axis.resolved import resolve_bytes

        self.data, self.name, self.settings, self.defaults = data, name, settings, defaults
        self.old = Counter((d.code, d.parameter) for d in before.diagnostics)
        self.was = resolve_bytes(data, name, defaults)
        self.count = 0

    def keeps(self, group: list[Diagnostic]) -> bool:
        """Whether applying all of `group`'s fixes changes the resolved axis only in their own
        parameters and adds no finding."""
        from ..axis.resolved import resolve_bytes

        self.count += 1
        source, applied = apply_edits(decode(self.data), [d.fix for d in group if d.fix is not None])
        if applied != len(group):
            return False  # overlapping edits: not all of them were tried
        new_data = source.encode()
        after = lint_file(new_data, self.name, self.settings, self.defaults)
        if after.error:
            return False
        old = self.old.copy()
        old.subtract((d.code, d.parameter) for d in group)
        if Counter((d.code, d.parameter) for d in after.diagnostics) - +old:
            return False  # a finding that was not there before
        now = resolve_bytes(new_data, self.name, self.defaults)
        paths = set(self.was.set_paths()) | set(now.set_paths())
        changed = {path for path in paths if repr(self.was.get(path)) != repr(now.get(path))}
        return changed <= {d.parameter for d in group}

    def risky(self, result: FileResult) -> tuple[set[int], set[int]]:
        """(fixes that change what the CNC does, fixes left unchecked) among the safe fixes of `result`,
        by index: groups that keep behaviour pass whole, groups that do not are halved."""
        candidates = [
            i
            for i, d in enumerate(result.diagnostics)
            if d.fix is not None and d.fix.applicability == "safe" and not d.fix.remove_bom
        ]
        failing: set[int] = set()
        unchecked: set[int] = set()
        groups = [candidates] if candidates else []
        while groups:
            group = groups.pop()
            if self.count >= MAX_CHECKS:
                unchecked.update(group)
                continue
            if self.keeps([result.diagnostics[i] for i in group]):
                continue
            if len(group) == 1:
                failing.update(group)
                continue
            half = len(group) // 2
            groups += [group[half:], group[:half]]
        return failing, unchecked


def _demoted(result: FileResult, unsafe: set[int], why: str = "changes what the CNC does") -> None:
    """Mark the fixes that failed (or could not be given) the behaviour test as unsafe in what is
    reported."""
    for index in unsafe:
        d = result.diagnostics[index]
        if d.fix is None:
            continue
        d.fix = replace(d.fix, applicability="unsafe", description=f"{d.fix.description} ({why})")


def check_fixes(
    data: bytes, name: str, settings: FileSettings | None, result: FileResult, defaults: bytes | None
) -> None:
    """Give every safe fix of `result` (a lint of `data`) the behaviour test; demote those that fail it or
    were not checked. A plain lint calls it too, so the fixes it calls safe are those --fix applies."""
    failing, unchecked = _Check(data, name, settings, result, defaults).risky(result)
    _demoted(result, failing)
    _demoted(result, unchecked, "not checked: too many fixes in one list, run --fix again or review them")


def fix_bytes(
    data: bytes,
    name: str,
    settings: FileSettings | None = None,
    *,
    unsafe: bool = False,
    defaults: bytes | None = None,
) -> FixOutcome:
    """Fix what can be fixed; the result holds the diagnostics that remain. `defaults` is the default list
    the CNC loads under the list: the fixes are checked, and what remains is found, with it underneath, so
    the findings of a fixing run are those a plain lint of the fixed list reports."""
    fixed = 0
    result = lint_file(data, name, settings, defaults)
    safe = {id(d) for d in result.diagnostics if d.fix is not None and d.fix.applicability == "safe"}
    refused: frozenset[tuple[str, int, int]] = frozenset()
    checked = False  # whether `result`'s safe fixes have had the behaviour test
    for round_ in range(MAX_ROUNDS):
        if result.error:
            break
        check_fixes(data, name, settings, result, defaults)
        if round_ == 0:
            refused = frozenset(
                (d.code, d.line, d.column)
                for d in result.diagnostics
                if id(d) in safe and d.fix is not None and d.fix.applicability != "safe"
            )
        checked = True
        allowed = {"safe", "unsafe"} if unsafe else {"safe"}
        fixes = [d.fix for d in result.diagnostics if d.fix is not None and d.fix.applicability in allowed]
        if not fixes:
            break
        source, applied = apply_edits(decode(data), fixes)
        new_data = source.encode()
        if not applied or new_data == data:
            break
        fixed += applied
        data = new_data
        result = lint_file(data, name, settings, defaults)
        checked = False
    if not result.error and not checked:
        check_fixes(data, name, settings, result, defaults)
    return FixOutcome(data, fixed, result, refused)

"""
What
----
A symbolic value that the parameter does not know, for example a misspelt
homing type. The message names the closest accepted symbol.

Lists of other kinds than axis lists combine flags with `|` and free spacing
(`error_protocol_mode  REPORT | REPORT_EXTENDED |PRINT` in the SDK's start-up
list): there every flag must be a symbol of the parameter, and a finding about
a flag after the first has no fix.

Why
---
An unknown symbol is rejected when the list is read and the parameter keeps
its default, which for `kenngr.homing.homing_type` means a different homing
strategy than the one you configured.

Example
-------
```
kenngr.antr_typ                2          ( SERCOS
kenngr.homing.homing_type      DRIVE_CONROLLED
```

Use instead
-----------
```
kenngr.antr_typ                2
kenngr.homing.homing_type      DRIVE_CONTROLLED
```

Reference
---------
P-AXIS-00299 value table; documented inconsistency B.14 (`DRIVE_CONROLLED` is a typo in the manual).
"""

from __future__ import annotations

import difflib
from collections.abc import Iterator
from functools import lru_cache
from typing import TYPE_CHECKING

from ..axis.analysis import combined_flags
from ..axis.facts import UnknownSymbol
from ._common import value_facts

if TYPE_CHECKING:
    from ..axis.analysis import Setting
    from ..catalogue import Parameter
    from ..core.diagnostics import Diagnostic
    from .context import Context

CODE = "LIS203"
NAME = "unknown-symbol"
FIX = "sometimes"
SUMMARY = "Unknown symbol for an enumerated parameter"

FACTS = (UnknownSymbol,)


@lru_cache(maxsize=1024)
def _similar(text: str, accepted: tuple[str, ...]) -> tuple[tuple[float, str], ...]:
    """(similarity, symbol) of the accepted symbols at least 0.6 alike, most alike first: computed once per
    written word (the message and the fix both use it; a list repeats the same typo on many lines)."""
    matcher = difflib.SequenceMatcher()
    matcher.set_seq2(text)
    scored = []
    for symbol in accepted:
        matcher.set_seq1(symbol)
        if matcher.real_quick_ratio() >= 0.6 and matcher.quick_ratio() >= 0.6 and matcher.ratio() >= 0.6:
            scored.append((matcher.ratio(), symbol))
    return tuple(sorted(scored, reverse=True))


def _closest(fact: UnknownSymbol) -> str | None:
    """The accepted symbol the written word most likely meant, for the message."""
    similar = _similar(fact.text, tuple(fact.accepted))
    if similar:
        return similar[0][1]
    return fact.text.upper() if fact.text.upper() in fact.accepted else None


def replacement(fact: UnknownSymbol) -> str | None:
    """A fix only for an unambiguous, close match (or the same word in capitals)."""
    strong = [symbol for score, symbol in _similar(fact.text, tuple(fact.accepted))[:2] if score >= 0.8]
    if not strong and _closest(fact) == fact.text.upper():
        return fact.text.upper()
    return strong[0] if len(strong) == 1 else None


def message(fact: UnknownSymbol, setting: Setting, parameter: Parameter) -> str:
    text = f"`{fact.text}` is not a value of `{setting.canonical}`"
    closest = _closest(fact)
    if closest:
        text += f" (did you mean `{closest}`?)"
    text += "; accepted: " + ", ".join(fact.accepted)
    if fact.codes:
        text += " (or their numbers " + ", ".join(str(code) for code in fact.codes) + ")"
    return text


def _one_of_flags(fact: UnknownSymbol, setting: Setting) -> bool:
    """A flag of an OR-combined value (`REPORT | REPORTT`) other than the written value token: replacing
    the token would change another flag, so such a finding has no fix."""
    return combined_flags(setting.line) is not None and fact.text != setting.line.value


def check(ctx: Context) -> Iterator[Diagnostic]:
    yield from value_facts(ctx, CODE, FACTS, message, replacement, applicability="safe", skip=_one_of_flags)
    if not ctx.axis_list:  # OR-combined flags are read in lists of other kinds only
        yield from value_facts(
            ctx, CODE, FACTS, message, skip=lambda fact, setting: not _one_of_flags(fact, setting)
        )

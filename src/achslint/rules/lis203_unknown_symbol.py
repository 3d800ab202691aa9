"""
What
----
A symbolic value that the parameter does not know, for example a misspelt
homing type. The message names the closest accepted symbol.

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
from typing import TYPE_CHECKING

from ..facts import UnknownSymbol
from ._common import value_facts

if TYPE_CHECKING:
    from ..analysis import Setting
    from ..catalogue import Parameter
    from ..context import Context
    from ..diagnostics import Diagnostic

CODE = "LIS203"
NAME = "unknown-symbol"
SEVERITY = "error"
FIX = "sometimes"
SUMMARY = "Unknown symbol for an enumerated parameter"

FACTS = (UnknownSymbol,)


def _closest(fact: UnknownSymbol) -> str | None:
    """The accepted symbol the written word most likely meant, for the message."""
    match = difflib.get_close_matches(fact.text, fact.accepted, n=1, cutoff=0.6)
    if match:
        return match[0]
    return fact.text.upper() if fact.text.upper() in fact.accepted else None


def replacement(fact: UnknownSymbol) -> str | None:
    """A fix only for an unambiguous, close match (or the same word in capitals)."""
    strong = difflib.get_close_matches(fact.text, fact.accepted, n=2, cutoff=0.8)
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


def check(ctx: Context) -> Iterator[Diagnostic]:
    yield from value_facts(ctx, CODE, FACTS, message, replacement, applicability="safe")

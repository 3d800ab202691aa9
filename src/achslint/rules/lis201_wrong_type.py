"""
What
----
A value of the wrong type: text or a real number for an integer parameter,
anything but 0/1 for a BOOLEAN, a number for a real parameter written as text,
or no value at all for a parameter that needs a number.

Why
---
The CNC rejects the value when it reads the list (the parameter keeps its
previous value) or, worse, truncates it. `2` for a BOOLEAN is not "more on";
`1.5` for a UNS32 loses its fraction.

Example
-------
```
kenngr.ref_richt                 2
getriebe[0].vb_refmax            100000.5
kenngr.fast_from_cam             yes
```

Use instead
-----------
```
kenngr.ref_richt                 1
getriebe[0].vb_refmax            100000
kenngr.fast_from_cam             1
```

Reference
---------
Data types of the catalogue (P-AXIS parameter pages); BOOLEAN is 0/1 (axis parameter manual, data types).
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from ..axis.facts import MissingValue, NotBoolean, RealForInteger, TextForNumber
from ._common import expected, value_facts

if TYPE_CHECKING:
    from ..axis.analysis import Setting
    from ..catalogue import Parameter
    from ..core.diagnostics import Diagnostic
    from .context import Context

CODE = "LIS201"
NAME = "wrong-type"
FIX = "sometimes"
SUMMARY = "Value of the wrong data type"

Fact = MissingValue | NotBoolean | RealForInteger | TextForNumber
FACTS: tuple[type[Fact], ...] = (MissingValue, NotBoolean, RealForInteger, TextForNumber)


def message(fact: Fact, setting: Setting, parameter: Parameter) -> str:
    name = setting.canonical
    if isinstance(fact, MissingValue):
        starts = f" (`{fact.comment}` starts a comment)" if fact.comment else ""
        return f"`{name}` has no value{starts}; {expected(parameter)} is expected"
    if isinstance(fact, NotBoolean):
        return f"`{name}` is BOOLEAN: write 0 (off) or 1 (on), not `{fact.text}`"
    if isinstance(fact, RealForInteger):
        text = f"`{name}` is an integer parameter ({parameter.type}) but `{fact.text}` is a real number"
        return text + (f"; write `{fact.replacement}`" if fact.replacement else "")
    return f"`{name}` expects {expected(parameter)}, not the text `{fact.text}`"


def replacement(fact: Fact) -> str | None:
    return fact.replacement if isinstance(fact, (NotBoolean, RealForInteger)) else None


def check(ctx: Context) -> Iterator[Diagnostic]:
    yield from value_facts(ctx, CODE, FACTS, message, replacement, applicability="unsafe")

"""
What
----
A string value longer than the parameter can hold: axis names (15
characters), drive ident names (29), telegram element names (29) and so on.

Why
---
The CNC keeps the text in a fixed-size field; a longer value is cut off or
rejected, and a cut drive ident no longer names the drive parameter you meant.

Example
-------
```
kopf.log_achs_name     Spindle_Main_Left_Side
```

Use instead
-----------
```
kopf.log_achs_name     S1_LEFT
```

Reference
---------
Maximum string lengths of the parameter metadata (e.g. P-AXIS-00297: 15 characters).
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from ..axis.facts import TooLong
from ._common import value_facts

if TYPE_CHECKING:
    from ..axis.analysis import Setting
    from ..catalogue import Parameter
    from ..core.diagnostics import Diagnostic
    from .context import Context

CODE = "LIS206"
NAME = "string-too-long"
FIX = "none"
SUMMARY = "String longer than the parameter allows"

FACTS = (TooLong,)


def message(fact: TooLong, setting: Setting, parameter: Parameter) -> str:
    return (
        f"`{setting.canonical}` is {fact.length} characters long; the CNC stores at most "
        f"{fact.max_length} characters for this parameter, shorten the value"
    )


def check(ctx: Context) -> Iterator[Diagnostic]:
    yield from value_facts(ctx, CODE, FACTS, message)

"""
What
----
An array index outside the array: `getriebe[6]` (gear stages are 0..5),
`lr_hw[2]` (0..1), `antr.fixed_stop.drive_ident[4]` (0..3).

Only the axis catalogue has array sizes so far: the reference tables of the
other list kinds (params-chan.tsv, params-tool.tsv ...) leave the "max array
size" column empty, so in those lists the rule has no bound to check and finds
nothing until their catalogues carry the sizes.

Why
---
The CNC rejects the line while reading the list; the value you wrote is lost.
Indices are zero-based, so the sixth gear stage is `getriebe[5]`.

Example
-------
```
getriebe[6].vb_refmax          100000
```

Use instead
-----------
```
getriebe[5].vb_refmax          100000
```

Reference
---------
Array bounds of the parameter metadata (catalogue `index_bounds`).
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from ..axis.facts import IndexOutOfBounds
from ._common import value_facts

if TYPE_CHECKING:
    from ..axis.analysis import Setting
    from ..catalogue import Parameter
    from ..core.diagnostics import Diagnostic
    from .context import Context

CODE = "LIS104"
NAME = "index-out-of-bounds"
FIX = "none"
SUMMARY = "Array index out of bounds"

FACTS = (IndexOutOfBounds,)


def message(fact: IndexOutOfBounds, setting: Setting, parameter: Parameter) -> str:
    shown = fact.index if fact.index is not None else f"`{fact.written}`"
    return (
        f"index {shown} of `{fact.array}` in `{setting.line.path}` is out of bounds: {parameter.id} allows "
        f"{fact.array}[{fact.low}]..{fact.array}[{fact.high}] (indices are zero-based)"
    )


def check(ctx: Context) -> Iterator[Diagnostic]:
    yield from value_facts(ctx, CODE, FACTS, message)

"""
What
----
The list has no end marker line `Ende`.

Why
---
Every list the CNC and TwinCAT write ends with `Ende`, and tools that read
lists look for that exact line to find the end. A list without it may be
truncated (a copy or an export that stopped early) and is not guaranteed to be
read the same way.

Example
-------
```
kopf.achs_nr          1
getriebe[0].vb_refmax 100000
```

Use instead
-----------
```
kopf.achs_nr          1
getriebe[0].vb_refmax 100000
Ende
```

Reference
---------
List format facts §4: every real list ends with `Ende`.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from ..core.diagnostics import Diagnostic, Edit, Fix
from ..syntax import parser as syntax

if TYPE_CHECKING:
    from .context import Context

CODE = "LIS002"
NAME = "missing-end-marker"
FIX = "safe"
SUMMARY = "List does not end with `Ende`"


def check(ctx: Context) -> Iterator[Diagnostic]:
    lines = ctx.file.lines
    if ctx.file.end_index is not None or any(syntax.is_misspelt_end(line) for line in lines):
        return
    last = lines[-1]
    if last.body == "":
        edit = Edit(last.number, 1, last.number, 1, "Ende" + ctx.newline)
    else:
        edit = Edit(
            last.number, last.end_column, last.number, last.end_column, ctx.newline + "Ende" + ctx.newline
        )
    yield ctx.report(
        CODE,
        last,
        "the list has no `Ende` line; add `Ende` as the last line",
        column=1,
        end_column=max(last.end_column, 2),
        fix=Fix("safe", "append the end marker `Ende`", (edit,)),
    )

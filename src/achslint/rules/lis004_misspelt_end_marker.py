"""
What
----
The end marker is written `End` (or `END`, `ende`) instead of `Ende`.

Why
---
Only the German `Ende` is the end marker. `End` is read as an unknown
parameter name, so the list has no end marker at all and anything after it is
read as well. The English edition of the homing manual prints `End`; real lists
always use `Ende`.

Example
-------
```
getriebe[0].pos_refpkt -2025000
End
```

Use instead
-----------
```
getriebe[0].pos_refpkt -2025000
Ende
```

Reference
---------
Documented inconsistency E.46 (end marker); list format facts §4.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from ..core.diagnostics import Diagnostic, Edit, Fix
from ..syntax import parser as syntax

if TYPE_CHECKING:
    from .context import Context

CODE = "LIS004"
NAME = "misspelt-end-marker"
FIX = "safe"
SUMMARY = "`End` written instead of the end marker `Ende`"


def check(ctx: Context) -> Iterator[Diagnostic]:
    stop = ctx.file.end_index if ctx.file.end_index is not None else len(ctx.file.lines)
    for line in ctx.file.lines[:stop]:
        if syntax.is_misspelt_end(line):
            start, end = ctx.path_span(line)
            yield ctx.report(
                CODE,
                line,
                f"`{line.path}` is not the end marker; the CNC only recognises `Ende`",
                column=start,
                end_column=end,
                fix=Fix(
                    "safe",
                    f"replace `{line.path}` with `Ende`",
                    (Edit(line.number, start, line.number, end, "Ende"),),
                ),
            )

"""
What
----
Parameter lines after the end marker `Ende`.

Why
---
The CNC stops reading at `Ende`, so every assignment below it is silently
ignored. This usually happens when lines are appended to a list by hand or by
a script that does not know about the end marker.

Example
-------
```
getriebe[0].vb_refmax 100000
Ende
getriebe[0].vb_reflow 20000
```

Use instead
-----------
```
getriebe[0].vb_refmax 100000
getriebe[0].vb_reflow 20000
Ende
```

Reference
---------
List format facts §4 (end marker; content after it is ignored).
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from ..core.diagnostics import Diagnostic, Related
from ..syntax import parser as syntax

if TYPE_CHECKING:
    from .context import Context

CODE = "LIS003"
NAME = "content-after-end"
FIX = "none"
SUMMARY = "Parameter lines after `Ende` are ignored by the CNC"


def check(ctx: Context) -> Iterator[Diagnostic]:
    end = ctx.file.end_index
    if end is None:
        return
    ignored = [line for line in ctx.file.lines[end + 1 :] if line.kind == syntax.ASSIGNMENT]
    if not ignored:
        return
    marker = ctx.file.lines[end]
    first, last = ignored[0], ignored[-1]
    count = len(ignored)
    noun = "line" if count == 1 else "lines"
    yield ctx.report(
        CODE,
        first,
        f"{count} parameter {noun} after `Ende` (line {marker.number}) {'is' if count == 1 else 'are'} ignored by "
        f"the CNC; move {'it' if count == 1 else 'them'} above `Ende` or delete {'it' if count == 1 else 'them'}",
        end_line=last.number,
        end_column=last.end_column,
        related=(Related(ctx.name, marker.number, marker.path_column, None, "end marker"),),
    )

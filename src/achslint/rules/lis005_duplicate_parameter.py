"""
What
----
The same parameter (same path and indices) is assigned more than once in a
list. The message says which value the CNC uses (the later one).

Why
---
The CNC reads the list from top to bottom and keeps the later value; the
earlier assignment has no effect. Vendor lists sometimes do this on purpose
(ISG's SERCOS-over-EtherCAT sample lists set `kenngr.antr_typ` in the general
part and again in the drive part), so it is a warning, not an error. With
different values the list says two things at once and the next person to edit
it may change the one that has no effect.

Example
-------
```
kenngr.antr_typ        8
...
kenngr.antr_typ        2
```

Use instead
-----------
```
kenngr.antr_typ        2
```

Reference
---------
List format facts §7 (repetition); SDK message 2056 "parameter already has a value".
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from ..core.diagnostics import Diagnostic
    from .context import Context

CODE = "LIS005"
NAME = "duplicate-parameter"
FIX = "none"
SUMMARY = "Parameter assigned more than once"


def check(ctx: Context) -> Iterator[Diagnostic]:
    for canonical, group in ctx.analysis.by_canonical().items():
        if len(group) < 2:
            continue
        keys = [repr(s.comparable) for s in group]
        spellings = {s.spelling for s in group}
        if len(set(keys)) > 1 and "old" in spellings and len(spellings) > 1:
            continue  # an alias and its parameter disagree: LIS103 reports it
        first = group[0]
        # Shared by every repetition of this parameter: a list repeated n times stays small.
        related = (ctx.related(first, "first assignment"),)
        same = (
            f"`{canonical}` is assigned again with the same value (first on line {first.line.number}); "
            f"delete the repetition"
        )
        for setting, key in zip(group[1:], keys[1:], strict=False):
            differs = key != keys[0]
            if differs:
                message = (
                    f"`{canonical}` is assigned again with a different value: the CNC uses this later one "
                    f"(`{setting.written_value}`), not `{first.written_value}` from line {first.line.number}; "
                    f"keep only the one you mean"
                )
            else:
                message = same
            start, end = ctx.path_span(setting.line)
            yield ctx.report(
                CODE,
                setting.line,
                message,
                column=start,
                end_column=end,
                setting=setting,
                related=related,
            )

"""
What
----
A parameter is set under its current name and under its old name (alias) with
different values, for example `kenngr.homing_type` and
`kenngr.homing.homing_type`. Only the axis catalogue has old names so far
(see LIS102).

Why
---
Both lines set the same CNC parameter. Only one value can win, and a reader of
the list sees two contradicting settings; typically one was added later
without noticing the other.

Example
-------
```
kenngr.antr_typ                2          ( SERCOS
kenngr.homing_type             CNC_CONTROLLED
kenngr.homing.homing_type      DRIVE_CONTROLLED
```

Use instead
-----------
```
kenngr.antr_typ                2
kenngr.homing.homing_type      DRIVE_CONTROLLED
```

Reference
---------
Documented inconsistency A.2 (both spellings accepted; conflicting values are an error).
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from ..axis.analysis import Setting
    from ..core.diagnostics import Diagnostic
    from .context import Context

CODE = "LIS103"
NAME = "alias-conflict"
FIX = "none"
SUMMARY = "Parameter and its old name set with different values"


def check(ctx: Context) -> Iterator[Diagnostic]:
    for canonical, group in ctx.analysis.by_canonical().items():
        if len(group) < 2:
            continue  # set once, under one name: nearly every parameter of a list
        spellings = {s.spelling for s in group}
        if "old" not in spellings or len(spellings) < 2:
            continue
        first = group[0]
        for setting in group[1:]:
            if setting.spelling == first.spelling or repr(setting.comparable) == repr(first.comparable):
                continue
            start, end = ctx.path_span(setting.line)
            yield ctx.report(
                CODE,
                setting.line,
                f"`{setting.line.path}` = `{setting.written_value}` contradicts `{first.line.path}` = "
                f"`{first.written_value}` on line {first.line.number}; both set {_id(setting)} "
                f"`{canonical}`, keep one",
                column=start,
                end_column=end,
                setting=setting,
                related=(ctx.related(first, "first assignment"),),
            )


def _id(setting: Setting) -> str:
    parameter = setting.parameter
    return parameter.id if parameter is not None else ""

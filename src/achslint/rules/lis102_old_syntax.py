"""
What
----
A parameter written with its old name, which the CNC still accepts, for
example `kenngr.homing_type` for `kenngr.homing.homing_type`.

Old names come from the catalogue: only the axis catalogue has any so far, so
in lists of other kinds the rule finds nothing until their tables list some.

Why
---
The old names keep working, but the manuals, the catalogue and newer tools use
the new ones; mixing both in one machine makes lists hard to compare and hides
duplicates. A safe fix renames it.

Example
-------
```
kenngr.homing_type             CNC_CONTROLLED
```

Use instead
-----------
```
kenngr.homing.homing_type      CNC_CONTROLLED
```

Reference
---------
P-AXIS-00299 (footnote on the older notation); documented inconsistency A.2.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from ._common import replace_path_fix

if TYPE_CHECKING:
    from ..core.diagnostics import Diagnostic
    from .context import Context

CODE = "LIS102"
NAME = "old-syntax"
FIX = "safe"
SUMMARY = "Old parameter name (still accepted)"


def check(ctx: Context) -> Iterator[Diagnostic]:
    for setting, parameter, canonical in ctx.known:
        alias = setting.resolution.alias if setting.resolution is not None else None
        if alias is not None and alias.kind == "old":  # written with its old name (`Setting.spelling`)
            line = setting.line
            start, end = ctx.path_span(line)
            yield ctx.report(
                CODE,
                line,
                f"`{line.path}` is the old name of {parameter.id} `{canonical}`; "
                f"it still works, but prefer the current name",
                column=start,
                end_column=end,
                setting=setting,
                fix=replace_path_fix(line, canonical, "safe"),
            )

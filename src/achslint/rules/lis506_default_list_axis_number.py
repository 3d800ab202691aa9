"""
What
----
A default axis list (a list named `default*mds*.lis`, like the
`default_mds.lis` a start-up list loads as `default_achs_mds`) that gives a
logical axis number `kopf.achs_nr` other than 0.

Why
---
The default list lies underneath every axis list of the machine; it is no axis
of its own, and the CNC checks that: a default list whose logical axis number
is not 0 aborts the start-up (P-ERR-110300). Leaving the line out counts as 0.
The usual cause is a default list made by copying an axis list.

Example
-------
```
# file: default_mds.lis
kopf.achs_nr          1          ( copied from achsmds1.lis
kenngr.antr_typ       1
Ende
```

Use instead
-----------
```
# file: default_mds.lis
kenngr.antr_typ       1
Ende
```

Reference
---------
P-ERR-110300 (a default axis list needs logical axis number 0, absent counts
as 0; otherwise the start-up is aborted), P-AXIS-00016 (logical axis number),
P-STUP-00035 (the default axis list named by the start-up list).
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from ..core.diagnostics import Diagnostic
    from .context import Context

CODE = "LIS506"
NAME = "default-list-axis-number"
FIX = "none"
SUMMARY = "Default axis list with a logical axis number other than 0"


def check(ctx: Context) -> Iterator[Diagnostic]:
    if not ctx.default_list:
        return
    for setting in ctx.settings:
        value = setting.value
        if setting.canonical == "kopf.achs_nr" and isinstance(value, int) and value != 0:
            start, end = ctx.value_span(setting.line)
            yield ctx.report(
                CODE,
                setting.line,
                f"a default axis list is no axis: kopf.achs_nr {value} makes the CNC abort the start-up "
                "(P-ERR-110300); remove the line or set 0",
                column=start,
                end_column=end,
                setting=setting,
            )

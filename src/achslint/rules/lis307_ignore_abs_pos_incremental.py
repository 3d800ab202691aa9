"""
What
----
`kenngr.homing.homing_type IGNORE_ABS_POS` on an axis without an absolute
measuring system (`kenngr.abs_pos_gueltig` is 0).

Why
---
IGNORE_ABS_POS makes G74 skip the axis because its absolute encoder already
knows the position. An incremental axis skipped that way is never homed; the
CNC warns with P-ERR-110584.

Example
-------
```
kenngr.abs_pos_gueltig          0
kenngr.homing.homing_type       IGNORE_ABS_POS
```

Use instead
-----------
```
kenngr.abs_pos_gueltig          1          ( absolute encoder fitted
kenngr.homing.homing_type       IGNORE_ABS_POS
```

Reference
---------
P-AXIS-00299 (IGNORE_ABS_POS only with P-AXIS-00014 = 1; P-ERR-110584).
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from ..core.diagnostics import Diagnostic
    from .context import Context

CODE = "LIS307"
NAME = "ignore-abs-pos-incremental"
FIX = "none"
PARAMETERS = ("kenngr.homing.homing_type", "kenngr.abs_pos_gueltig")  # parameters this rule reads
SUMMARY = "`IGNORE_ABS_POS` without an absolute measuring system"


def check(ctx: Context) -> Iterator[Diagnostic]:
    values = ctx.values
    if values.homing_type == "IGNORE_ABS_POS" and not values.get("kenngr.abs_pos_gueltig"):
        yield ctx.cross(
            CODE,
            f"homing type IGNORE_ABS_POS needs an absolute measuring system, but {ctx.show('kenngr.abs_pos_gueltig')}; "
            "the CNC warns (P-ERR-110584) and the axis is never homed",
            ["kenngr.homing.homing_type", "kenngr.abs_pos_gueltig"],
        )

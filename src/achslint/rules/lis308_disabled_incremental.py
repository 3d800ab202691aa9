"""
What
----
`kenngr.homing.homing_type DISABLED` on an incremental axis
(`kenngr.abs_pos_gueltig` 0).

Why
---
DISABLED refuses every homing command (G74 ends with an error). It is meant
for axes with an absolute measuring system; an incremental axis configured
this way can never be homed, so its software limits are never active.

Example
-------
```
kenngr.abs_pos_gueltig          0
kenngr.homing.homing_type       DISABLED
```

Use instead
-----------
```
kenngr.homing.homing_type       CNC_CONTROLLED
```

Reference
---------
P-AXIS-00299 (DISABLED: only for axes with P-AXIS-00014 = 1; CNC errors P-ERR-50686 / P-ERR-60313).
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from ..core.diagnostics import Diagnostic
    from .context import Context

CODE = "LIS308"
NAME = "disabled-incremental"
FIX = "none"
PARAMETERS = ("kenngr.homing.homing_type", "kenngr.abs_pos_gueltig")  # parameters this rule reads
SUMMARY = "`DISABLED` homing on an incremental axis"


def check(ctx: Context) -> Iterator[Diagnostic]:
    values = ctx.values
    if values.homing_type == "DISABLED" and not values.get("kenngr.abs_pos_gueltig"):
        yield ctx.cross(
            CODE,
            f"homing is DISABLED but the axis is incremental ({ctx.show('kenngr.abs_pos_gueltig')}): it can never be "
            "homed and G74 ends with an error; use a homing type that moves, or set abs_pos_gueltig for an absolute encoder",
            ["kenngr.homing.homing_type", "kenngr.abs_pos_gueltig"],
        )

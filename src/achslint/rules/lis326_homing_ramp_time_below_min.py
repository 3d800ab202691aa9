"""
What
----
A homing ramp time `getriebe[i].tr_ref` other than 0 but shorter than the
minimum ramp time of the same gear stage, `getriebe[i].dynamik.tr_min`. The
ramp time takes effect with a non-linear slope (`getriebe[i].slope_type` other
than 0); with a linear slope LIS401 says it has no effect.

Why
---
The CNC reports P-ERR-110394 while it loads the list and ramps with `tr_min`
instead, so homing accelerates and brakes more gently than written. A value of
0 is no error: it asks for `tr_min` on purpose (§3.2.4). `explain` and
`dry-run` show the corrected value.

Example
-------
```
kenngr.antr_typ                 1          ( conventional drive
getriebe[0].slope_type          2          ( non-linear slope
getriebe[0].dynamik.tr_min      20000      ( µs
getriebe[0].tr_ref              5000       ( µs, shorter than tr_min
```

Use instead
-----------
```
kenngr.antr_typ                 1
lr_hw[0].cam_direct_access      0          ( cam signal from the PLC
getriebe[0].slope_type          2
getriebe[0].dynamik.tr_min      20000
getriebe[0].tr_ref              20000      ( at least tr_min, or 0 for tr_min
```

Reference
---------
P-AXIS-00286 (range P-AXIS-00201 ≤ tr_ref; 0 or too small: P-AXIS-00201 is used, TF5200 homing manual
§3.2.4); P-AXIS-00201; CNC message P-ERR-110394.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from ..core.diagnostics import Diagnostic
    from .context import Context

CODE = "LIS326"
NAME = "homing-ramp-time-below-min"
FIX = "none"
PARAMETERS = ("getriebe[i].tr_ref", "getriebe[i].dynamik.tr_min")  # parameters this rule reads
SUMMARY = "Homing ramp time `tr_ref` below `tr_min` (the CNC raises it)"


def check(ctx: Context) -> Iterator[Diagnostic]:
    for gear in ctx.values.gear_stages_set("tr_ref"):
        path, limit = f"getriebe[{gear}].tr_ref", f"getriebe[{gear}].dynamik.tr_min"
        correction = ctx.correction(path)
        if correction is not None:
            yield ctx.report_correction(
                CODE,
                correction,
                f"gear stage {gear}: {ctx.show(path)} is shorter than {ctx.show(limit)}",
                [path, limit],
            )

"""
What
----
A homing acceleration `getriebe[i].a_ref` above the maximum acceleration of the
same gear stage, `getriebe[i].dynamik.a_max`.

Why
---
The homing acceleration may be at most the axis's maximum acceleration. The
CNC reports P-ERR-110393 while it loads the list and homes with `a_max`
instead, so the axis accelerates and brakes over other distances than the
list suggests: where it comes to a stop after the cam and after the reference
point changes with it. `explain` and `dry-run` show and simulate the corrected
value.

Example
-------
```
kenngr.antr_typ                 1          ( conventional drive
getriebe[0].dynamik.a_max       500        ( mm/s²
getriebe[0].a_ref               2000       ( mm/s², above a_max
```

Use instead
-----------
```
kenngr.antr_typ                 1
lr_hw[0].cam_direct_access      0          ( cam signal from the PLC
getriebe[0].dynamik.a_max       500
getriebe[0].a_ref               500        ( at most a_max
```

Reference
---------
P-AXIS-00285 (range 0 ≤ a_ref ≤ P-AXIS-00008; 0 selects the fallback of TF5200 homing manual §3.2.4);
P-AXIS-00008; CNC message P-ERR-110393.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from ..core.diagnostics import Diagnostic
    from .context import Context

CODE = "LIS325"
NAME = "homing-acceleration-above-max"
FIX = "none"
PARAMETERS = ("getriebe[i].a_ref", "getriebe[i].dynamik.a_max")  # parameters this rule reads
SUMMARY = "Homing acceleration `a_ref` above `a_max` (the CNC lowers it)"


def check(ctx: Context) -> Iterator[Diagnostic]:
    for gear in ctx.values.gear_stages_set("a_ref"):
        path, limit = f"getriebe[{gear}].a_ref", f"getriebe[{gear}].dynamik.a_max"
        correction = ctx.correction(path)
        if correction is not None:
            yield ctx.report_correction(
                CODE,
                correction,
                f"gear stage {gear}: {ctx.show(path)} is above {ctx.show(limit)}",
                [path, limit],
            )

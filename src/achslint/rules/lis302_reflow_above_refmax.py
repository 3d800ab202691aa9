"""
What
----
In a gear stage, the slow homing speed `vb_reflow` is higher than the fast
one `vb_refmax`. Each gear stage is checked on its own; defaults count for the
value the list leaves out. Applies where both speeds are used: homing with a
reference cam and the zero pulse in three phases or in one (elsewhere one of
them has no effect, LIS401).

Why
---
The manual requires vb_refmax ≥ vb_reflow: the cam is searched fast and the
reference is taken slowly, because the slow speed decides the repeatability.
Swapped values make homing slow and the reference inaccurate.

Example
-------
```
kenngr.antr_typ                 1          ( conventional drive, cam and zero pulse
getriebe[0].vb_refmax           20000
getriebe[0].vb_reflow           100000
```

Use instead
-----------
```
kenngr.antr_typ                 1
getriebe[0].vb_refmax           100000
getriebe[0].vb_reflow           20000
lr_hw[0].cam_direct_access      0          ( cam signal from the PLC
```

Reference
---------
TF5200 homing manual §3.2.3; ranges of P-AXIS-00218 (1 ≤ vb_reflow ≤ P-AXIS-00219) and P-AXIS-00219.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from ..core.diagnostics import Diagnostic
    from .context import Context

CODE = "LIS302"
NAME = "reflow-above-refmax"
FIX = "none"
PARAMETERS = ("getriebe[i].vb_reflow", "getriebe[i].vb_refmax")  # parameters this rule reads
SUMMARY = "`vb_reflow` higher than `vb_refmax` in a gear stage"


def check(ctx: Context) -> Iterator[Diagnostic]:
    values = ctx.values
    for gear in values.gear_stages_set("vb_reflow", "vb_refmax"):
        slow, fast = f"getriebe[{gear}].vb_reflow", f"getriebe[{gear}].vb_refmax"
        if values.number(slow) > values.number(fast) and ctx.effective(slow, fast):
            yield ctx.cross(
                CODE,
                f"gear stage {gear}: slow homing speed {ctx.show(slow)} is higher than the fast one {ctx.show(fast)}; "
                "vb_refmax must be at least vb_reflow",
                [slow, fast],
            )

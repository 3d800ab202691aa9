"""
What
----
In a gear stage, the fast homing speed `vb_refmax` is higher than the axis's
maximum speed `dynamik.vb_max`, or higher than the speed limit for axes that
are not yet homed (`vb_not_referenced`, when it is set).

Why
---
The range of P-AXIS-00219 ends at P-AXIS-00212 (an error). Above
vb_not_referenced the CNC caps vb_refmax and warns with P-ERR-110421, so that
case is reported as a warning. Either way the axis does not home at the speed
written in the list.

Example
-------
```
getriebe[0].dynamik.vb_max      100000
getriebe[0].vb_refmax           150000
```

Use instead
-----------
```
getriebe[0].dynamik.vb_max      100000
getriebe[0].vb_refmax           80000
```

Reference
---------
P-AXIS-00219 range (P-AXIS-00218 ≤ vb_refmax ≤ P-AXIS-00212); P-AXIS-00268; CNC message P-ERR-110421.
"""

from __future__ import annotations

from ..diagnostics import Severity

CODE = "LIS303"
NAME = "refmax-above-limits"
SEVERITY = "error"
FIX = "none"
PARAMETERS = ("getriebe[i].vb_refmax", "getriebe[i].dynamik.vb_max", "getriebe[i].vb_not_referenced")  # parameters this rule reads
SUMMARY = "`vb_refmax` above `vb_max` or `vb_not_referenced`"


def check(ctx):
    values = ctx.values
    for gear in values.gear_stages_set("vb_refmax", "dynamik.vb_max", "vb_not_referenced"):
        fast, vmax, unref = (f"getriebe[{gear}].vb_refmax", f"getriebe[{gear}].dynamik.vb_max",
                             f"getriebe[{gear}].vb_not_referenced")
        if values.get(fast) > values.get(vmax):
            yield ctx.cross(
                CODE,
                f"gear stage {gear}: fast homing speed {ctx.show(fast)} is above the maximum axis speed "
                f"{ctx.show(vmax)}; lower vb_refmax",
                [fast, vmax],
            )
        elif values.get(unref) and values.get(fast) > values.get(unref):
            yield ctx.cross(
                CODE,
                f"gear stage {gear}: fast homing speed {ctx.show(fast)} is above the limit for unreferenced axes "
                f"{ctx.show(unref)}; the CNC caps it (P-ERR-110421), lower vb_refmax",
                [fast, unref], severity=Severity.WARNING,
            )

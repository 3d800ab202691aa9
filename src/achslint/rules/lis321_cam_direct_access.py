"""
What
----
Homing with a reference cam where the list sets `lr_hw[0].cam_direct_access
1` (or `lr_hw[1]`) instead of 0.

Why
---
For homing with a cam the manual describes one way to deliver the cam signal:
`cam_direct_access 0`, the PLC writes it into the HLI (§3.1.2.3; column
"cam_direct_access 0" of the table in §3.5 for types I and III). Direct access
is not available on TwinCAT systems, so a cam that is meant to come from the
PLC is not read. Only an explicit 1 in the list is reported.

Example
-------
```
kenngr.antr_typ              1          ( conventional drive
kenngr.ref_ohne_nocken       0
lr_hw[0].cam_direct_access   1
```

Use instead
-----------
```
kenngr.antr_typ              1
kenngr.ref_ohne_nocken       0
lr_hw[0].cam_direct_access   0          ( cam signal from the PLC via the HLI
```

Reference
---------
TF5200 homing manual §3.1.2.3 and §3.5; P-AXIS-00036 (not available for TwinCAT systems).
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from ..context import Context
    from ..diagnostics import Diagnostic

CODE = "LIS321"
NAME = "cam-direct-access"
SEVERITY = "warning"
FIX = "none"
PARAMETERS = ("lr_hw[i].cam_direct_access", "kenngr.ref_ohne_nocken")  # parameters this rule reads
SUMMARY = "Cam homing with `cam_direct_access 1` instead of the HLI"


def check(ctx: Context) -> Iterator[Diagnostic]:
    values = ctx.values
    if not ctx.strategy.with_cam:
        return
    for index in (0, 1):
        path = f"lr_hw[{index}].cam_direct_access"
        if values.is_set(path) and values.get(path) and ctx.effective(path):
            yield ctx.cross(
                CODE,
                f"{ctx.show(path)}: homing with a cam reads the cam signal the PLC writes into the HLI only with "
                "cam_direct_access 0 (§3.1.2.3); direct access is not available on TwinCAT systems; set it to 0",
                [path, "kenngr.ref_ohne_nocken"],
            )

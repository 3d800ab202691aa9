"""
What
----
Homing with a reference cam where `lr_hw[0].cam_direct_access` is 1 instead
of 0 — written in the list or left at its default, which is 1 — on a drive type
the parameter is for (conventional, terminal, Lightbus, PROFIDRIVE).
`lr_hw[1].cam_direct_access` is judged the same way where the list sets it.

Why
---
For homing with a cam the manual describes one way to deliver the cam signal:
`cam_direct_access 0`, the PLC writes it into the HLI (§3.1.2.3; column
"cam_direct_access 0" of the table in §3.5 for types I and III). Direct access
is not available on TwinCAT systems, so a cam that is meant to come from the
PLC is not read. The default is 1, so a cam list that leaves the parameter out
has the same problem as one that writes 1 (`explain` shows the default as the
value in force); the manual's example list for a conventional drive (§3.6.1)
writes 0.

Example
-------
```
kenngr.antr_typ              1          ( conventional drive
kenngr.ref_ohne_nocken       0
lr_hw[0].cam_direct_access   1
```

```
kenngr.antr_typ              1          ( conventional drive
kenngr.ref_ohne_nocken       0          ( cam_direct_access left at its default, 1
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
TF5200 homing manual §3.1.2.3, §3.5 and the example list of §3.6.1; P-AXIS-00036 (default 1; drive types conventional, terminal, Lightbus,
PROFIDRIVE; not available for TwinCAT systems).
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from ..axis.drives import DriveType

if TYPE_CHECKING:
    from ..core.diagnostics import Diagnostic
    from .context import Context

CODE = "LIS321"
NAME = "cam-direct-access"
FIX = "none"
PARAMETERS = ("lr_hw[i].cam_direct_access", "kenngr.ref_ohne_nocken")  # parameters this rule reads
SUMMARY = "Cam homing with `cam_direct_access 1` instead of the HLI"

# The drive types P-AXIS-00036 names: the CNC reads the cam itself only with these (SERCOS and CANopen drives
# deliver it as antr.reference_cam_signal says, LIS323).
READING_DRIVES = {DriveType.CONVENTIONAL, DriveType.PROFIDRIVE, DriveType.LIGHTBUS, DriveType.TERMINAL}


def check(ctx: Context) -> Iterator[Diagnostic]:
    values = ctx.values
    if not ctx.strategy.with_cam or values.drive_type not in READING_DRIVES:
        return
    for index in (0, 1):
        path = f"lr_hw[{index}].cam_direct_access"
        # lr_hw[0] is the input homing reads, so its default counts as much as a written 1; lr_hw[1] (a second
        # input) only where the list uses it.
        judged = index == 0 or values.is_set(path)
        if judged and values.get(path) and ctx.effective(path):
            remedy = "set it to 0" if values.is_set(path) else f"write `{path} 0`"
            yield ctx.cross(
                CODE,
                f"{ctx.show(path)}: homing with a cam reads the cam signal the PLC writes into the HLI only with "
                f"cam_direct_access 0 (§3.1.2.3); direct access is not available on TwinCAT systems; {remedy}",
                [path, "kenngr.ref_ohne_nocken"],
            )

"""
What
----
`antr.reference_cam_signal` names an input the drive type does not have:
SERCOS offers `PLC`, `RT_STATUS_BIT_1` and `RT_STATUS_BIT_2`; CANopen `PLC`
and `STATUS_DIG_INPUTS` (older lists: `DIG_INPUT_1` … `DIG_INPUT_4`); every
other drive reads the cam from the PLC only. Checked where the cam takes
effect (CNC-controlled homing with a cam).

Why
---
The CNC cannot read the cam from an input the drive does not provide, so the
cam is never seen and homing runs to a limit.

Example
-------
```
kenngr.antr_typ             8          ( CANopen
antr.reference_cam_signal   RT_STATUS_BIT_1
```

Use instead
-----------
```
kenngr.antr_typ             8
antr.reference_cam_signal   STATUS_DIG_INPUTS
```

Reference
---------
P-AXIS-00321 (inputs per drive type; real-time status bits only with NC-controlled homing; P-ERR-70292).
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from ..axis.drives import DriveType

if TYPE_CHECKING:
    from ..core.diagnostics import Diagnostic
    from .context import Context

CODE = "LIS323"
NAME = "reference-cam-input"
FIX = "none"
PARAMETERS = ("antr.reference_cam_signal", "kenngr.antr_typ")  # parameters this rule reads
SUMMARY = "Reference cam read from an input the drive type does not have"

SIGNAL = "antr.reference_cam_signal"
INPUTS: dict[int, tuple[str, ...]] = {
    DriveType.SERCOS: ("PLC", "RT_STATUS_BIT_1", "RT_STATUS_BIT_2"),
    DriveType.CANOPEN: (
        "PLC",
        "STATUS_DIG_INPUTS",
        "DIG_INPUT_1",
        "DIG_INPUT_2",
        "DIG_INPUT_3",
        "DIG_INPUT_4",
    ),
}


def check(ctx: Context) -> Iterator[Diagnostic]:
    values = ctx.values
    value = values.get(SIGNAL)
    allowed = INPUTS.get(values.drive_type, ("PLC",))
    if value in allowed or not ctx.effective(SIGNAL):
        return
    yield ctx.cross(
        CODE,
        f"{ctx.show(SIGNAL)} is not an input of kenngr.antr_typ {values.drive_type} ({values.drive_name()}); "
        f"it offers {', '.join(allowed)}",
        [SIGNAL, "kenngr.antr_typ"],
    )

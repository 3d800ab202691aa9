"""
What
----
`kenngr.abs_pos_gueltig 1` (absolute measuring system, no homing) on a drive
type for which the parameter is not documented: it is listed for simulated,
SERCOS and CANopen drives only.

Why
---
With the flag the CNC treats the position after power-up as valid and never
moves the axis to home. Conventional, terminal, Lightbus, PROFIDRIVE and
real-time Ethernet drives deliver an incremental position, so the axis would
run in a coordinate system that was never synchronised with the machine.

Example
-------
```
kenngr.antr_typ           6          ( terminal
kenngr.abs_pos_gueltig    1
```

Use instead
-----------
```
kenngr.antr_typ           6
kenngr.abs_pos_gueltig    0          ( incremental: home it
lr_hw[0].cam_direct_access 0         ( cam signal from the PLC
```

Reference
---------
P-AXIS-00014 (drive types simulation, SERCOS, CANopen); TF5200 homing manual §2 (absolute or incremental
measuring system).
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from ..core.diagnostics import Diagnostic
    from .context import Context

CODE = "LIS324"
NAME = "absolute-flag-drive-type"
FIX = "none"
PARAMETERS = ("kenngr.abs_pos_gueltig", "kenngr.antr_typ")  # parameters this rule reads
SUMMARY = "Absolute measuring system declared on a drive type without one"

FLAG = "kenngr.abs_pos_gueltig"


def check(ctx: Context) -> Iterator[Diagnostic]:
    values = ctx.values
    drives = values.parameter(FLAG).drive_types
    if not values.get(FLAG) or not drives or values.drive_type in drives:
        return
    names = ", ".join(values.drive_name(code) for code in drives)
    yield ctx.cross(
        CODE,
        f"{ctx.show(FLAG)} on kenngr.antr_typ {values.drive_type} ({values.drive_name()}): the absolute position is "
        f"documented for {names} only; an incremental axis marked absolute is never homed",
        [FLAG, "kenngr.antr_typ"],
    )

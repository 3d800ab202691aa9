"""
What
----
Homing to a fixed stop (`TORQ`) on a drive type that cannot do it. Fixed-stop
homing works with SERCOS and CANopen drives, the DSE / generic drive interface
and simulated drives. When the list does not set `kenngr.antr_typ`, the CNC's
default drive type (4, simulation) counts.

Why
---
The CNC rejects it with P-ERR-110371; the axis cannot be homed as configured.

Example
-------
```
kenngr.antr_typ                 1          ( conventional
kenngr.homing.homing_type       TORQ
```

Use instead
-----------
A cam-based CNC-controlled homing on this drive, or a drive type that supports
fixed-stop homing:

```
kenngr.antr_typ                 1          ( conventional
kenngr.homing.homing_type       CNC_CONTROLLED
lr_hw[0].cam_direct_access      0          ( cam signal from the PLC
```

Reference
---------
TF5200 homing manual §2.3.3.4 (only SERCOS and CANopen; P-ERR-110371) and §2.3.3.5 (DSE: simulation and generic drive interface).
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from ..axis.drives import DriveType

if TYPE_CHECKING:
    from ..core.diagnostics import Diagnostic
    from .context import Context

CODE = "LIS306"
NAME = "torq-drive-type"
FIX = "none"
PARAMETERS = ("kenngr.homing.homing_type", "kenngr.antr_typ")  # parameters this rule reads
SUMMARY = "`TORQ` homing on a drive type without fixed-stop homing"
CNC_REFUSES_HOMING = True  # the CNC does not run this homing at all: a dry-run refuses with the finding

TORQ_DRIVES = {DriveType.SERCOS, DriveType.SIMULATION, DriveType.CANOPEN, DriveType.GENERIC, DriveType.DSE}


def check(ctx: Context) -> Iterator[Diagnostic]:
    values = ctx.values
    if values.homing_type == "TORQ" and values.drive_type not in TORQ_DRIVES:
        yield ctx.cross(
            CODE,
            f"fixed-stop homing (TORQ) is not possible with kenngr.antr_typ {values.drive_type} "
            f"({values.drive_name()}); the CNC rejects it with P-ERR-110371. It works with SERCOS, CANopen, "
            "DSE/generic and simulated drives",
            ["kenngr.homing.homing_type", "kenngr.antr_typ"],
        )

"""
What
----
Homing to a fixed stop (`TORQ`) on a SERCOS or CANopen drive whose list has no
`antr.fixed_stop.drive_ident[i]` entry with the identifier `TORQUE_LIMIT` (or
only one whose `commu` is `IGNORE`, which is never sent). With these drives the
CNC limits the torque by writing that entry to the drive at the start of homing.

Why
---
For homing to a fixed stop the drive's torque must be limited (§2.3.3.4.1);
the CNC does it through the drive parameters of "move to fixed stop"
(§2.3.3.4.3), where `TORQUE_LIMIT` is the identifier reserved for the torque
limit. Without it nothing limits the torque: the axis drives into the stop with
the drive's full torque, which can damage the mechanics, and detection by
torque has nothing to compare with. The CNC loads such a list without a
message, so this is a warning.

Example
-------
```
kenngr.antr_typ                             2          ( SERCOS
kenngr.homing.homing_type                   TORQ
kenngr.homing.torq_max_distance             200000
kenngr.homing.torq_detect_time              25000
getriebe[0].homing.torq_move_velocity       5000
getriebe[0].homing.torq_move_acceleration   100
```

Use instead
-----------
```
kenngr.antr_typ                             2
kenngr.homing.homing_type                   TORQ
kenngr.homing.torq_max_distance             200000
kenngr.homing.torq_detect_time              25000
getriebe[0].homing.torq_move_velocity       5000
getriebe[0].homing.torq_move_acceleration   100
antr.fixed_stop.drive_ident[0].id           TORQUE_LIMIT
antr.fixed_stop.drive_ident[0].wr_ident     S_0_0092   ( the drive's torque limit
antr.fixed_stop.drive_ident[0].active_value 50         ( while homing
```

Reference
---------
TF5200 homing manual §2.3.3.4.1 (the maximum torque must be limited), §2.3.3.4.3 (drive parameters
P-AXIS-00719 … P-AXIS-00731, written at the start of homing) and the SERCOS example of §2.3.3.4.6;
P-AXIS-00719 (`TORQUE_LIMIT` reserved and required for moving to a fixed stop), P-AXIS-00720.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from ..axis.drives import CANOPEN, SERCOS

if TYPE_CHECKING:
    from ..core.diagnostics import Diagnostic
    from .context import Context

CODE = "LIS328"
NAME = "fixed-stop-torque-not-limited"
FIX = "none"
PARAMETERS = (
    "kenngr.homing.homing_type",
    "kenngr.antr_typ",
    "antr.fixed_stop.drive_ident[i].id",
    "antr.fixed_stop.drive_ident[i].commu",
)  # parameters this rule reads
SUMMARY = "Fixed-stop homing on a drive whose torque is not limited"

ENTRIES = range(4)  # antr.fixed_stop.drive_ident[0..3]


def check(ctx: Context) -> Iterator[Diagnostic]:
    values = ctx.values
    if values.homing_type != "TORQ" or values.drive_type not in (SERCOS, CANOPEN) or not ctx.strategy.moves:
        return
    named = [i for i in ENTRIES if values.get(f"antr.fixed_stop.drive_ident[{i}].id") == "TORQUE_LIMIT"]
    sent = [i for i in named if values.get(f"antr.fixed_stop.drive_ident[{i}].commu") != "IGNORE"]
    if sent:
        return
    ignored = [f"antr.fixed_stop.drive_ident[{i}].commu" for i in named]
    found = (
        f"its TORQUE_LIMIT entry is not sent ({', '.join(f'`{p}` IGNORE' for p in ignored)})"
        if ignored
        else "no antr.fixed_stop.drive_ident[i].id is TORQUE_LIMIT"
    )
    yield ctx.cross(
        CODE,
        f"fixed-stop homing (TORQ) on kenngr.antr_typ {values.drive_type} ({values.drive_name()}) without a torque "
        f"limit: {found}, so the axis pushes into the stop with the drive's full torque (§2.3.3.4.1). Add an "
        "entry with id TORQUE_LIMIT, the drive's torque-limit object as wr_ident and the limit as active_value",
        ["kenngr.homing.homing_type", *ignored, "kenngr.antr_typ"],
    )

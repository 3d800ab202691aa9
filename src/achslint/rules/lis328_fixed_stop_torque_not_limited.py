"""
What
----
Homing to a fixed stop (`TORQ`) on a SERCOS or CANopen drive whose list has no
`antr.fixed_stop.drive_ident[i]` entry with the identifier `TORQUE_LIMIT`
(error), or only one whose `commu` is `IGNORE`, which is never sent (warning).
With these drives the CNC limits the torque by writing that entry to the drive
at the start of homing.

Why
---
For homing to a fixed stop the drive's torque must be limited (§2.3.3.4.1);
the CNC does it through the drive parameters of "move to fixed stop"
(§2.3.3.4.3), where `TORQUE_LIMIT` is the identifier reserved for the torque
limit and required for the move (P-AXIS-00719). Without such an entry the CNC
stops the homing when it starts with error P-ERR-70541 ("no drive ident
TORQUE_LIMIT configured for fixed-stop movement"): the axis is not homed, and
`achslint dry-run` refuses it with this finding. An entry that is configured
but not sent (`commu IGNORE`) leaves the torque unlimited: the axis pushes into
the stop with the drive's full torque, which can damage the mechanics, and
detection by torque has nothing to compare with. The manuals name no error for
that case, so it is a warning.

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
P-AXIS-00719 (`TORQUE_LIMIT` reserved and required for moving to a fixed stop), P-AXIS-00720 (`commu`);
P-ERR-70541 (no drive ident TORQUE_LIMIT configured for the fixed-stop movement; runtime error).
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from ..axis.drives import CANOPEN, SERCOS
from ..core.diagnostics import Severity

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
CNC_REFUSES_HOMING = True  # without TORQUE_LIMIT the CNC stops the homing (P-ERR-70541): a dry-run refuses
ALSO_SEVERITIES = (Severity.WARNING,)  # a TORQUE_LIMIT entry that is never sent (no documented CNC error)

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
    if not ignored:
        yield ctx.cross(
            CODE,
            f"fixed-stop homing (TORQ) on kenngr.antr_typ {values.drive_type} ({values.drive_name()}) without a "
            "torque limit: no antr.fixed_stop.drive_ident[i].id is TORQUE_LIMIT, which the move to a fixed stop "
            "requires (P-AXIS-00719), so the CNC stops the homing at its start with error P-ERR-70541. Add an "
            "entry with id TORQUE_LIMIT, the drive's torque-limit object as wr_ident and the limit as active_value",
            ["kenngr.homing.homing_type", "kenngr.antr_typ"],
        )
        return
    listed = ", ".join(f"`{path}` IGNORE" for path in ignored)
    yield ctx.cross(
        CODE,
        f"fixed-stop homing (TORQ) on kenngr.antr_typ {values.drive_type} ({values.drive_name()}) without a torque "
        f"limit: its TORQUE_LIMIT entry is not sent ({listed}), so the axis pushes into the stop with the drive's "
        "full torque (§2.3.3.4.1). Send it: set its commu to ACYCLIC (or CYCLIC)",
        ["kenngr.homing.homing_type", *ignored, "kenngr.antr_typ"],
        severity=Severity.WARNING,
    )

"""
What
----
A homing type the drive type does not support: `DRIVE_CONTROLLED` on a drive
other than SERCOS or CANopen (simulation, conventional, terminal, Lightbus,
real-time Ethernet, PROFIDRIVE only home CNC-controlled). Checked when the list
sets `kenngr.antr_typ`.

Why
---
The CNC reports P-ERR-110384 while reading the list and silently uses the
drive type's default homing type instead — a different sequence from the one
you configured.

Example
-------
```
kenngr.antr_typ                 4          ( simulation
kenngr.homing.homing_type       DRIVE_CONTROLLED
```

Use instead
-----------
```
kenngr.antr_typ                 4
kenngr.homing.homing_type       CNC_CONTROLLED
```

Reference
---------
P-AXIS-00299 (table of homing types per drive type; P-ERR-110384).
"""

from __future__ import annotations

from ..effective import default_homing_type

CODE = "LIS305"
NAME = "homing-type-vs-drive"
SEVERITY = "error"
FIX = "none"
PARAMETERS = ("kenngr.homing.homing_type", "kenngr.antr_typ")  # parameters this rule reads
SUMMARY = "Homing type not supported by the drive type"

# Drive types that only home CNC-controlled (P-AXIS-00299 table, plus the conventional drive).
CNC_ONLY = {1, 3, 4, 5, 6, 7}


def check(ctx):
    values = ctx.values
    if not values.drive_type_known or values.homing_type_is_default:
        return
    drive = values.drive_type
    if values.homing_type == "DRIVE_CONTROLLED" and drive in CNC_ONLY:
        fallback = default_homing_type(drive)
        yield ctx.cross(
            CODE,
            f"`kenngr.homing.homing_type` DRIVE_CONTROLLED is not available for kenngr.antr_typ {drive} "
            f"({values.drive_name()}); the CNC reports P-ERR-110384 and uses {fallback} instead",
            ["kenngr.homing.homing_type", "kenngr.antr_typ"],
        )

"""
What
----
Spindle homing set up so it cannot run: a simulated spindle (`kenngr.achs_typ
4`, `kenngr.antr_typ 4`) without `kenngr.ref_ohne_rev = 1`, or a SERCOS spindle
homed drive-controlled without the `KEINE_AUTO_RPF` bit (0x100) in
`kenngr.achs_mode`.

Why
---
A simulated spindle must home without reversal. A drive-controlled SERCOS
spindle must not start the CNC's automatic homing before positioning (M19);
the KEINE_AUTO_RPF bit suppresses it.

Example
-------
```
kenngr.achs_typ                4
kenngr.antr_typ                2
kenngr.achs_mode               0x4
kenngr.homing.homing_type      DRIVE_CONTROLLED
```

Use instead
-----------
```
kenngr.achs_mode               0x104      ( MODULO | KEINE_AUTO_RPF
```

Reference
---------
TF5200 homing manual §3.1.1.1 (simulation axis) and §2.3.2 / "Homing with SERCOS drives" (KEINE_AUTO_RPF); P-AXIS-00015, P-AXIS-00157.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from ..core.diagnostics import Diagnostic
    from .context import Context

CODE = "LIS314"
NAME = "spindle-homing"
FIX = "none"
PARAMETERS = (
    "kenngr.ref_ohne_rev",
    "kenngr.achs_mode",
    "kenngr.achs_typ",
    "kenngr.antr_typ",
)  # parameters this rule reads
SUMMARY = "Spindle homing without the settings a spindle needs"

KEINE_AUTO_RPF = 0x100


def check(ctx: Context) -> Iterator[Diagnostic]:
    values = ctx.values
    if values.axis_type != "S":
        return
    drive = values.drive_type
    if drive == 4 and not values.get("kenngr.ref_ohne_rev") and values.homing_type == "CNC_CONTROLLED":
        yield ctx.cross(
            CODE,
            f"a simulated spindle must home without reversal, but {ctx.show('kenngr.ref_ohne_rev')}; set it to 1",
            ["kenngr.ref_ohne_rev", "kenngr.achs_typ", "kenngr.antr_typ"],
        )
    mode = values.get("kenngr.achs_mode")
    if (
        drive == 2
        and values.homing_type == "DRIVE_CONTROLLED"
        and isinstance(mode, int)
        and not mode & KEINE_AUTO_RPF
    ):
        yield ctx.cross(
            CODE,
            f"a SERCOS spindle with drive-controlled homing needs the KEINE_AUTO_RPF bit (0x100) in "
            f"`kenngr.achs_mode` ({mode:#x}); without it the CNC starts an automatic homing before the spindle positions (M19). Use {mode | KEINE_AUTO_RPF:#x}",
            ["kenngr.achs_mode", "kenngr.homing.homing_type", "kenngr.antr_typ"],
        )

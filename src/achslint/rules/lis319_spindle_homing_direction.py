"""
What
----
A spindle that homes without reversal (flying homing, `kenngr.ref_ohne_rev 1`)
while its rotation is restricted to a preferred direction
(`kenngr.vorz_richtung 1`) that differs from the homing direction
(`kenngr.beweg_richt` ≠ `kenngr.ref_richt`). Both directions are compared as
written (1 = positive); check the drive's sense of rotation if they differ on
purpose.

Why
---
When the spindle's data are initialised the CNC checks the preferred direction
against the homing direction and reports an error when they differ; the
spindle then cannot be homed or positioned (M19).

Example
-------
```
kenngr.achs_typ        4          ( spindle
kenngr.antr_typ        1          ( conventional drive
kenngr.ref_ohne_rev    1
kenngr.vorz_richtung   1
kenngr.beweg_richt     1
kenngr.ref_richt       0
```

Use instead
-----------
```
kenngr.achs_typ        4
kenngr.antr_typ        1
kenngr.ref_ohne_rev    1
kenngr.vorz_richtung   1
kenngr.beweg_richt     1
kenngr.ref_richt       1          ( home in the preferred direction
kenngr.achs_mode       0x4        ( MODULO
```

Reference
---------
TF5200 homing manual §2.3.2.1 (homing without reversal: preferred direction checked against P-AXIS-00158);
P-AXIS-00031, P-AXIS-00224, P-AXIS-00158.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from ..core.diagnostics import Diagnostic
    from .context import Context

CODE = "LIS319"
NAME = "spindle-homing-direction"
FIX = "none"
PARAMETERS = ("kenngr.ref_richt", "kenngr.beweg_richt", "kenngr.vorz_richtung")  # parameters this rule reads
SUMMARY = "Spindle homing direction against its restricted preferred direction"
CNC_REFUSES_HOMING = True  # the CNC does not run this homing at all: a dry-run refuses with the finding

HOMING, PREFERRED, RESTRICTED = "kenngr.ref_richt", "kenngr.beweg_richt", "kenngr.vorz_richtung"


def check(ctx: Context) -> Iterator[Diagnostic]:
    values = ctx.values
    if not ctx.strategy.definition.flying or not values.get(RESTRICTED):
        return
    if bool(values.get(PREFERRED)) != bool(values.get(HOMING)) and ctx.effective(HOMING):
        yield ctx.cross(
            CODE,
            f"the spindle may only turn in its preferred direction ({ctx.show(RESTRICTED)}, {ctx.show(PREFERRED)}), "
            f"but homes the other way ({ctx.show(HOMING)}); the CNC reports an error when it initialises the "
            "spindle. Home in the preferred direction",
            [HOMING, PREFERRED, RESTRICTED],
        )

"""
What
----
A spindle homed CNC-controlled with reversal (`kenngr.ref_ohne_rev 0`,
conventional three-phase homing) whose automatic homing is not suppressed
(no KEINE_AUTO_RPF bit 0x100 in `kenngr.achs_mode`).

Why
---
The CNC homes a spindle by itself before M19 or a gear change when its
reference is missing or lost (for example after the encoder frequency was
exceeded). From endless rotation that only works without reversal: with
`ref_ohne_rev 0` the CNC reports an error and the spindle goes to its error
state. Homing from standstill still works, so this is a warning.

Example
-------
```
kenngr.achs_typ        4          ( spindle
kenngr.antr_typ        1          ( conventional drive
kenngr.ref_ohne_rev    0
```

Use instead
-----------
```
kenngr.achs_typ        4
kenngr.antr_typ        1
kenngr.ref_ohne_rev    1          ( flying homing, also from rotation
kenngr.achs_mode       0x4        ( MODULO
```

Reference
---------
TF5200 homing manual §2.3.2 (flying homing; "from endless rotation this can only be executed if ref_ohne_rev is
TRUE"); P-AXIS-00157, P-AXIS-00015 (KEINE_AUTO_RPF).
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from ..core.diagnostics import Diagnostic
    from .context import Context

CODE = "LIS320"
NAME = "spindle-homing-with-reversal"
FIX = "none"
PARAMETERS = ("kenngr.ref_ohne_rev", "kenngr.achs_mode", "kenngr.achs_typ")  # parameters this rule reads
SUMMARY = "Spindle homing with reversal cannot start from endless rotation"

KEINE_AUTO_RPF = 0x100


def check(ctx: Context) -> Iterator[Diagnostic]:
    values, strategy = ctx.values, ctx.strategy
    if values.axis_type != "S" or not strategy.definition.reverses:
        return
    mode = values.get("kenngr.achs_mode")
    if isinstance(mode, int) and mode & KEINE_AUTO_RPF:
        return
    yield ctx.cross(
        CODE,
        f"the spindle homes with reversal ({ctx.show('kenngr.ref_ohne_rev')}): when the CNC has to home it from "
        "endless rotation (before M19 or a gear change) it reports an error; set kenngr.ref_ohne_rev 1 for flying "
        "homing",
        ["kenngr.ref_ohne_rev", "kenngr.achs_typ"],
    )

"""
What
----
A homing type the drive type does not support: `DRIVE_CONTROLLED` on a drive
that only homes CNC-controlled (simulation, conventional, terminal, Lightbus,
real-time Ethernet, PROFIDRIVE). When the list does not set
`kenngr.antr_typ`, the CNC's default drive type (4, simulation) counts.

Why
---
The CNC reports P-ERR-110384 while it loads the list and runs the drive type's
default homing type instead — a different sequence from the one written.
`explain` and `dry-run` show the sequence the CNC actually runs, and the
parameters that matter for it.

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
P-AXIS-00299 (table of homing types per drive type; unsupported type corrected to the default, P-ERR-110384).
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from ..core.diagnostics import Diagnostic
    from .context import Context

CODE = "LIS305"
NAME = "homing-type-vs-drive"
FIX = "none"
PARAMETERS = ("kenngr.homing.homing_type", "kenngr.antr_typ")  # parameters this rule reads
SUMMARY = "Homing type not supported by the drive type (the CNC replaces it)"

TYPE = "kenngr.homing.homing_type"


def check(ctx: Context) -> Iterator[Diagnostic]:
    correction = ctx.correction(TYPE)
    if correction is None:
        return
    values = ctx.values
    unset = (
        ""
        if values.drive_type_known
        else " (kenngr.antr_typ is not set, so the CNC's default drive type counts)"
    )
    yield ctx.report_correction(
        CODE, correction, f"`{TYPE}` {correction.written}{unset}", [TYPE, "kenngr.antr_typ"]
    )

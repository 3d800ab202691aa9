"""
What
----
A spindle (`kenngr.achs_typ 4`) whose axis mode `kenngr.achs_mode` lacks the
MODULO bit (0x4). The mode's default is LINEAR (0x1), so a spindle list that
does not set `kenngr.achs_mode` is reported too.

Why
---
A spindle turns endlessly and always counts modulo. The CNC reports
P-ERR-110352 while it loads the list and corrects the mode to MODULO. The
finding names the mode the CNC uses: MODULO in place of LINEAR, the other bits
(such as KEINE_AUTO_RPF, 0x100) as written — the manual names only the MODULO
bit, so keeping the others is this tool's reading.

Example
-------
```
kenngr.achs_typ                 4          ( spindle
kenngr.antr_typ                 1          ( conventional drive
kenngr.ref_ohne_rev             1          ( flying homing
kenngr.achs_mode                0x1        ( LINEAR
```

```
kenngr.achs_typ                 4          ( spindle, kenngr.achs_mode not set: LINEAR
kenngr.antr_typ                 1
kenngr.ref_ohne_rev             1
```

Use instead
-----------
```
kenngr.achs_typ                 4
kenngr.antr_typ                 1
kenngr.ref_ohne_rev             1
kenngr.achs_mode                0x4        ( MODULO
```

Reference
---------
P-AXIS-00015 (spindles must be MODULO, else corrected), P-AXIS-00018; CNC message P-ERR-110352.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from ..core.diagnostics import Diagnostic
    from .context import Context

CODE = "LIS327"
NAME = "spindle-not-modulo"
FIX = "none"
PARAMETERS = ("kenngr.achs_mode", "kenngr.achs_typ")  # parameters this rule reads
SUMMARY = "Spindle whose axis mode is not MODULO (the CNC corrects it)"

MODE = "kenngr.achs_mode"


def check(ctx: Context) -> Iterator[Diagnostic]:
    values = ctx.values
    # Not `ctx.correction`: the axis mode is no homing parameter, no strategy lists it, yet it always counts.
    correction = values.correction(MODE)
    if correction is None or correction.error != "P-ERR-110352":
        return
    origin = "" if values.is_set(MODE) else " (default)"
    yield ctx.report_correction(
        CODE,
        correction,
        f"the spindle's `{MODE}` {_hex(correction.written)}{origin} has no MODULO bit (0x4); write "
        f"{_hex(correction.used)}",
        [MODE, "kenngr.achs_typ"],
    )


def _hex(value: object) -> str:
    return f"{value:#x}" if isinstance(value, int) else str(value)

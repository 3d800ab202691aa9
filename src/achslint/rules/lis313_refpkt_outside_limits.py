"""
What
----
The reference position `getriebe[i].pos_refpkt` does not lie strictly between
the software limits `kenngr.swe_neg` and `kenngr.swe_pos`, where the strategy
uses it (CNC-controlled sequences, compatibility mode NONE, a gantry slave,
drive-controlled homing with write_reference_position_to_drive). Spindles are
not checked (software limits do not apply to them).

Why
---
The range of P-AXIS-00152 is swe_neg < pos_refpkt < swe_pos. After homing the
software limits become active; an axis homed outside them stands in a
forbidden zone and refuses further moves in one direction.

Example
-------
```
kenngr.swe_neg                 -10000000
kenngr.swe_pos                  10000000
getriebe[0].pos_refpkt         -12000000
```

Use instead
-----------
```
getriebe[0].pos_refpkt          -9500000
```

Reference
---------
P-AXIS-00152 range (swe_neg < pos_refpkt < swe_pos); TF5200 homing manual §2 (software limits after homing).
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from ..core.diagnostics import Diagnostic
    from .context import Context

CODE = "LIS313"
NAME = "refpkt-outside-limits"
FIX = "none"
PARAMETERS = ("getriebe[i].pos_refpkt", "kenngr.swe_neg", "kenngr.swe_pos")  # parameters this rule reads
SUMMARY = "`pos_refpkt` not between the software limits"

NEG, POS = "kenngr.swe_neg", "kenngr.swe_pos"


def check(ctx: Context) -> Iterator[Diagnostic]:
    values = ctx.values
    if values.axis_type == "S":
        return
    stages = values.gear_stages_set("pos_refpkt")
    if values.is_set(NEG) or values.is_set(POS):
        stages = sorted(set(stages) | {0})
    low, high = values.number(NEG), values.number(POS)
    for gear in stages:
        path = f"getriebe[{gear}].pos_refpkt"
        position = values.number(path)
        if not low < position < high and ctx.effective(path):
            side = NEG if position <= low else POS
            yield ctx.cross(
                CODE,
                f"gear stage {gear}: reference position {ctx.show(path)} is not inside the software limits "
                f"({ctx.show(NEG)}, {ctx.show(POS)}); move it inside or widen {side}",
                [path, side],
            )

"""
What
----
A homing speed of a gear stage above what the axis may run: `vb_refmax` or
`vb_reflow` above the axis's maximum speed `dynamik.vb_max`, or a homing speed
(`vb_refmax`, `vb_reflow`, `homing.torq_move_velocity`) above the limit for
axes that are not yet homed (`vb_not_referenced`, when it is set). Only speeds
that the configured strategy uses are checked (LIS401 reports the others).

Why
---
The ranges of P-AXIS-00218/00219 end at P-AXIS-00212 (P-ERR-110147/110148).
Above vb_not_referenced the CNC lowers the speed to that limit while it loads
the list (P-ERR-110421 vb_refmax, P-ERR-110422 vb_reflow, P-ERR-110413
torq_move_velocity): the axis homes slower than written, and `explain` and
`dry-run` show the lowered speed.

Example
-------
```
kenngr.antr_typ                 1          ( conventional drive, cam and zero pulse
getriebe[0].vb_not_referenced   50000
getriebe[0].vb_refmax           150000
```

Use instead
-----------
```
kenngr.antr_typ                 1
getriebe[0].vb_not_referenced   50000
getriebe[0].vb_refmax           50000
lr_hw[0].cam_direct_access      0          ( cam signal from the PLC
```

Reference
---------
P-AXIS-00218, P-AXIS-00219 ranges (≤ P-AXIS-00212); P-AXIS-00268; P-AXIS-00333; CNC messages P-ERR-110147,
P-ERR-110148, P-ERR-110421, P-ERR-110422, P-ERR-110413.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from ..axis.corrections import CAPPED_SPEEDS

if TYPE_CHECKING:
    from ..core.diagnostics import Diagnostic
    from .context import Context

CODE = "LIS303"
NAME = "refmax-above-limits"
FIX = "none"
PARAMETERS = (
    "getriebe[i].vb_refmax",
    "getriebe[i].vb_reflow",
    "getriebe[i].dynamik.vb_max",
    "getriebe[i].vb_not_referenced",
    "getriebe[i].homing.torq_move_velocity",
)  # parameters this rule reads
SUMMARY = "Homing speed above `vb_max` or above `vb_not_referenced` (lowered by the CNC)"

_ABOVE_MAX = (
    ("vb_refmax", "fast homing speed", "P-ERR-110147"),
    ("vb_reflow", "slow homing speed", "P-ERR-110148"),
)


def check(ctx: Context) -> Iterator[Diagnostic]:
    values = ctx.values
    for gear in values.gear_stages_set("vb_refmax", "vb_reflow", "dynamik.vb_max"):
        vmax = f"getriebe[{gear}].dynamik.vb_max"
        for member, words, error in _ABOVE_MAX:
            path = f"getriebe[{gear}].{member}"
            if values.written_number(path) > values.number(vmax) and ctx.effective(path):
                yield ctx.cross(
                    CODE,
                    f"gear stage {gear}: {words} {ctx.show(path)} is above the maximum axis speed {ctx.show(vmax)} "
                    f"({error}); lower {member}",
                    [path, vmax],
                )
    for gear in values.gear_stages_set("vb_not_referenced"):
        unref = f"getriebe[{gear}].vb_not_referenced"
        for member, _ in CAPPED_SPEEDS:
            path = f"getriebe[{gear}].{member}"
            correction = ctx.correction(path)
            if correction is not None and values.written_number(path) <= values.number(
                f"getriebe[{gear}].dynamik.vb_max"
            ):
                yield ctx.report_correction(
                    CODE, correction, f"gear stage {gear}: {ctx.show(path)}", [path, unref]
                )

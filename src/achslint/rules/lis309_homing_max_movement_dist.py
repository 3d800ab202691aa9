"""
What
----
`kenngr.homing_max_movement_dist` (path monitoring during homing) set to a
value other than 0 on a linear axis, or, on a rotary axis or spindle, set
smaller than the modulo range (`getriebe[i].moduloo - getriebe[i].modulou`) of a
gear stage.

Why
---
Path monitoring only works for rotary axes and spindles: on a linear axis the
CNC reports P-ERR-110545 and forces the value to 0. On rotary axes the homing
move may need up to a whole revolution to find cam and zero pulse; a shorter
limit aborts homing with P-ERR-70394 although nothing is wrong.

Example
-------
```
kenngr.achs_typ                 2          ( rotary axis
getriebe[0].moduloo             3600000    ( 360°
kenngr.homing_max_movement_dist 1800000    ( 180°
```

Use instead
-----------
```
kenngr.achs_typ                 2
getriebe[0].moduloo             3600000
kenngr.homing_max_movement_dist 3600000    ( at least one revolution
```

Reference
---------
P-AXIS-00412 (axis types R, S; set at least to the modulo range); CNC messages P-ERR-110545, P-ERR-70394.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from ..core.diagnostics import Diagnostic
    from .context import Context

CODE = "LIS309"
NAME = "homing-max-movement-dist"
FIX = "none"
PARAMETERS = (
    "kenngr.homing_max_movement_dist",
    "kenngr.achs_typ",
    "getriebe[i].moduloo",
    "getriebe[i].modulou",
)  # parameters this rule reads
SUMMARY = "Homing path monitoring on a linear axis or shorter than the modulo range"

DIST = "kenngr.homing_max_movement_dist"


def check(ctx: Context) -> Iterator[Diagnostic]:
    values = ctx.values
    correction = ctx.correction(DIST)
    if correction is not None:
        assumed = (
            "" if values.is_set("kenngr.achs_typ") else " (kenngr.achs_typ is not set, so the axis is linear)"
        )
        yield ctx.report_correction(
            CODE, correction, f"{ctx.show(DIST)} on a linear axis{assumed}", [DIST, "kenngr.achs_typ"]
        )
        return
    limit = values.number(DIST)
    if not limit or values.axis_type == "T" or not ctx.effective(DIST):
        return
    for gear in sorted(set(values.gear_stages_set("moduloo", "modulou")) | {0}):
        upper, lower = f"getriebe[{gear}].moduloo", f"getriebe[{gear}].modulou"
        span = values.number(upper) - values.number(lower)
        if limit < span:
            yield ctx.cross(
                CODE,
                f"gear stage {gear}: {ctx.show(DIST)} is shorter than the modulo range ({ctx.show(upper)} - "
                f"{ctx.show(lower)} = {span}); homing may need a full revolution and would abort with P-ERR-70394; "
                f"use at least {span}",
                [DIST, upper, lower],
            )

"""
What
----
Fixed-stop homing: the minimum travel before stop detection
(`kenngr.homing.torq_min_distance`) is not smaller than the maximum travel
(`kenngr.homing.torq_max_distance`).

Why
---
Applies to homing to a fixed stop (`TORQ`); other strategies do not read these
parameters (LIS401). Detection is only armed after torq_min_distance and homing aborts after
torq_max_distance, so with min ≥ max the stop can never be detected.

Example
-------
```
kenngr.antr_typ                             2          ( SERCOS
kenngr.homing.homing_type                   TORQ
kenngr.homing.torq_detect_time              25000
getriebe[0].homing.torq_move_velocity       5000
getriebe[0].homing.torq_move_acceleration   100
kenngr.homing.torq_min_distance             200000     ( 20 mm
kenngr.homing.torq_max_distance             100000     ( 10 mm
```

Use instead
-----------
```
kenngr.antr_typ                             2
kenngr.homing.homing_type                   TORQ
kenngr.homing.torq_detect_time              25000
getriebe[0].homing.torq_move_velocity       5000
getriebe[0].homing.torq_move_acceleration   100
kenngr.homing.torq_min_distance             0
kenngr.homing.torq_max_distance             200000     ( 20 mm
antr.fixed_stop.drive_ident[0].id           TORQUE_LIMIT ( torque limited while homing
antr.fixed_stop.drive_ident[0].wr_ident     S_0_0092
antr.fixed_stop.drive_ident[0].active_value 50
```

Reference
---------
P-AXIS-00344 range (0 ≤ torq_min_distance ≤ P-AXIS-00345); TF5200 homing manual §2.3.3.4.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from ..core.diagnostics import Diagnostic
    from .context import Context

CODE = "LIS304"
NAME = "torq-distances"
FIX = "none"
PARAMETERS = (
    "kenngr.homing.torq_min_distance",
    "kenngr.homing.torq_max_distance",
)  # parameters this rule reads
SUMMARY = "`torq_min_distance` not below `torq_max_distance`"

MIN, MAX = "kenngr.homing.torq_min_distance", "kenngr.homing.torq_max_distance"


def check(ctx: Context) -> Iterator[Diagnostic]:
    values = ctx.values
    if not (values.is_set(MIN) or values.is_set(MAX)) or not ctx.effective(MIN, MAX):
        return  # only fixed-stop homing reads them
    low, high = values.number(MIN), values.number(MAX)
    if (low or high) and low >= high:
        yield ctx.cross(
            CODE,
            f"{ctx.show(MIN)} is not below {ctx.show(MAX)}: stop detection starts only after the minimum travel "
            "and homing aborts at the maximum, so the stop is never found; make the maximum larger",
            [MIN, MAX],
        )

"""
What
----
`antr.sercos.drive_supports_cnc_homing = 1` (the SERCOS drive latches the zero
pulse with command S-0-146 during CNC-controlled homing) configured
inconsistently: without `antr.cnc_homing_encoder` (0 = not configured), on a
spindle, or with `antr.sercos.cnc_homing_rt_bit_layout` outside 1..16. Checked
where the latch takes effect: a SERCOS drive homing CNC-controlled on the zero
pulse (on another drive LIS105 reports the parameter, without zero pulse LIS401).

Why
---
The drive-supported latch needs to know which encoder to use and which
real-time bits carry the handshake; it is not available for spindles and only
exists for SERCOS. On a spindle the CNC switches it off (P-ERR-110522); an
invalid bit layout is corrected to 1 (P-ERR-110514), which rarely matches the
drive's configuration.

Example
-------
```
kenngr.antr_typ                         2          ( SERCOS
kenngr.homing.homing_type               CNC_CONTROLLED
antr.sercos.drive_supports_cnc_homing   1
```

Use instead
-----------
```
kenngr.antr_typ                         2
kenngr.homing.homing_type               CNC_CONTROLLED
kenngr.homing_without_zero_pulse        0
antr.sercos.drive_supports_cnc_homing   1
antr.cnc_homing_encoder                 1          ( read from S-0-147
antr.sercos.cnc_homing_rt_bit_layout    16
```

Reference
---------
TF5200 homing manual §3.1.1.2 and §3.6.3; P-AXIS-00386 (P-ERR-110522), P-AXIS-00387 (P-ERR-110514), P-AXIS-00388.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from ..core.diagnostics import Diagnostic
    from .context import Context

CODE = "LIS312"
NAME = "sercos-drive-latch"
FIX = "none"
PARAMETERS = (
    "antr.sercos.drive_supports_cnc_homing",
    "antr.cnc_homing_encoder",
    "antr.sercos.cnc_homing_rt_bit_layout",
)  # parameters this rule reads
SUMMARY = "Drive-supported CNC homing (S-0-146) configured inconsistently"

LATCH, ENCODER, LAYOUT = (
    "antr.sercos.drive_supports_cnc_homing",
    "antr.cnc_homing_encoder",
    "antr.sercos.cnc_homing_rt_bit_layout",
)


def check(ctx: Context) -> Iterator[Diagnostic]:
    values = ctx.values
    spindle = ctx.correction(LATCH)
    if spindle is not None:
        yield ctx.report_correction(CODE, spindle, ctx.show(LATCH), [LATCH, "kenngr.achs_typ"])
        return
    if not values.get(LATCH) or not ctx.effective(LATCH):
        return  # another drive type (LIS105) or a strategy without zero-pulse search (LIS401)
    if not values.get(ENCODER):
        yield ctx.cross(
            CODE,
            f"{ctx.show(LATCH)} but {ctx.show(ENCODER)} (not configured): set 1 (from S-0-147), "
            "2 (motor encoder) or 3 (external encoder)",
            [ENCODER, LATCH],
        )
    layout = ctx.correction(LAYOUT)
    if layout is not None:
        yield ctx.report_correction(CODE, layout, ctx.show(LAYOUT), [LAYOUT, LATCH])

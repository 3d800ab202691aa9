"""
What
----
`antr.sercos.drive_supports_cnc_homing = 1` (the SERCOS drive latches the zero
pulse with command S-0-146 during CNC-controlled homing) configured
inconsistently: without `antr.cnc_homing_encoder` (0 = not configured), on a
drive that is not SERCOS, on a spindle, together with
`homing_without_zero_pulse = 1`, or with `antr.sercos.cnc_homing_rt_bit_layout`
outside 1..16.

Why
---
The drive-supported latch needs to know which encoder to use and which
real-time bits carry the handshake; it is not available for spindles and only
exists for SERCOS. An invalid bit layout is corrected to 1 (P-ERR-110514),
which rarely matches the drive's configuration.

Example
-------
```
kenngr.antr_typ                         2
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
TF5200 homing manual §3.1.1.2 and §3.6.3; P-AXIS-00386, P-AXIS-00387 (P-ERR-110514), P-AXIS-00388.
"""

from __future__ import annotations

CODE = "LIS312"
NAME = "sercos-drive-latch"
SEVERITY = "error"
FIX = "none"
PARAMETERS = ("antr.sercos.drive_supports_cnc_homing", "antr.cnc_homing_encoder", "antr.sercos.cnc_homing_rt_bit_layout", "kenngr.homing_without_zero_pulse")  # parameters this rule reads
SUMMARY = "Drive-supported CNC homing (S-0-146) configured inconsistently"

LATCH, ENCODER, LAYOUT = "antr.sercos.drive_supports_cnc_homing", "antr.cnc_homing_encoder", "antr.sercos.cnc_homing_rt_bit_layout"


def check(ctx):
    values = ctx.values
    if not values.get(LATCH):
        return
    if values.drive_type_known and values.drive_type != 2:
        yield ctx.cross(CODE, f"{ctx.show(LATCH)} only exists for SERCOS drives; this axis has kenngr.antr_typ "
                              f"{values.drive_type} ({values.drive_name()})", [LATCH, "kenngr.antr_typ"])
        return
    if values.axis_type == "S":
        yield ctx.cross(CODE, f"{ctx.show(LATCH)} is not supported for spindles (kenngr.achs_typ 4)", [LATCH, "kenngr.achs_typ"])
    if not values.get(ENCODER):
        yield ctx.cross(CODE, f"{ctx.show(LATCH)} but {ctx.show(ENCODER)} (not configured): set 1 (from S-0-147), "
                              "2 (motor encoder) or 3 (external encoder)", [ENCODER, LATCH])
    if values.get("kenngr.homing_without_zero_pulse"):
        yield ctx.cross(CODE, f"{ctx.show(LATCH)} latches the zero pulse, but "
                              f"{ctx.show('kenngr.homing_without_zero_pulse')}; set it to 0",
                        [LATCH, "kenngr.homing_without_zero_pulse"])
    layout = values.get(LAYOUT)
    if not 1 <= layout <= 16:
        yield ctx.cross(CODE, f"{ctx.show(LAYOUT)} must be 1..16 when {LATCH} is 1; the CNC corrects it to 1 "
                              "(P-ERR-110514), which must match the bits assigned in the drive", [LAYOUT, LATCH])

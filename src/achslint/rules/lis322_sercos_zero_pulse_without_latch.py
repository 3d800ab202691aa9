"""
What
----
A SERCOS drive homed CNC-controlled on the zero pulse without a way to latch
it: no drive-supported latch (`antr.sercos.drive_supports_cnc_homing 0`), no
AX5000 latch (`kenngr.echtzeit_bit_nr` 0) and no encoder-overflow homing
(`kenngr.homing_overflow_evaluation 0`).

Why
---
The CNC does not search the zero pulse of a SERCOS drive itself (§2.2: only
"without zero pulse search"). It needs one of the methods of §3.1.1.2: the
drive's latch via command S-0-146, the AX5000 latch reported as a measured
value (real-time bit in `echtzeit_bit_nr`), or the encoder overflow. Without
them the zero pulse is never found. Referencing on the cam edge
(`homing_without_zero_pulse 1`) or drive-controlled homing need none.

Example
-------
```
kenngr.antr_typ                   2
kenngr.homing.homing_type         CNC_CONTROLLED
kenngr.homing_without_zero_pulse  0
```

Use instead
-----------
```
kenngr.antr_typ                         2
kenngr.homing.homing_type               CNC_CONTROLLED
kenngr.homing_without_zero_pulse        0
antr.sercos.drive_supports_cnc_homing   1
antr.cnc_homing_encoder                 1
antr.sercos.cnc_homing_rt_bit_layout    16
```

Reference
---------
TF5200 homing manual §2.2 (NC-controlled referencing of SERCOS drives without zero pulse search), §3.1.1.2
(S-0-146, AX5000 latch with P-AXIS-00060, encoder overflow), §3.6.3; P-AXIS-00386, P-AXIS-00060, P-AXIS-00294.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from ..core.diagnostics import Diagnostic
    from .context import Context

CODE = "LIS322"
NAME = "sercos-zero-pulse-without-latch"
FIX = "none"
PARAMETERS = (
    "kenngr.homing_without_zero_pulse",
    "antr.sercos.drive_supports_cnc_homing",
    "kenngr.echtzeit_bit_nr",
    "kenngr.homing_overflow_evaluation",
)  # parameters this rule reads
SUMMARY = "SERCOS CNC-controlled homing on a zero pulse nobody latches"

PULSE = "kenngr.homing_without_zero_pulse"


def check(ctx: Context) -> Iterator[Diagnostic]:
    # one reading for the rule and the dry-run, which fails such a homing with this code
    if not ctx.strategy.unlatched_zero_pulse:
        return
    yield ctx.cross(
        CODE,
        f"the SERCOS drive homes CNC-controlled on the zero pulse ({ctx.show(PULSE)}), but nothing latches it: set "
        "antr.sercos.drive_supports_cnc_homing 1 (S-0-146), configure the AX5000 latch (kenngr.echtzeit_bit_nr), "
        "use encoder-overflow homing, or reference on the cam edge",
        [PULSE, "kenngr.homing.homing_type", "kenngr.antr_typ"],
    )

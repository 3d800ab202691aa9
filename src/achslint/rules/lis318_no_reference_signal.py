"""
What
----
CNC-controlled homing with neither a reference cam (`kenngr.ref_ohne_nocken
1`) nor a zero pulse (`kenngr.homing_without_zero_pulse 1`, and no
encoder-overflow homing): nothing marks the reference position.

Why
---
Without a cam the reference must be a zero pulse (§2.3.3.3); without a zero
pulse it must be the cam edge (§2.3.1.3). With both switched off the axis
moves in the homing direction until a limit switch or the path monitoring
stops it, and homing never completes.

Example
-------
```
kenngr.antr_typ                    1          ( conventional drive
kenngr.ref_ohne_nocken             1
kenngr.ref_ohne_rev                1
kenngr.homing_without_zero_pulse   1
```

Use instead
-----------
```
kenngr.antr_typ                    1
kenngr.ref_ohne_nocken             1
kenngr.ref_ohne_rev                1
kenngr.homing_without_zero_pulse   0          ( reference on the zero pulse
```

Reference
---------
TF5200 homing manual §2.3.3.3 (zero pulse without cam), §3.1.2.1, §3.1.3, §3.5 (types I–III); P-AXIS-00084,
P-AXIS-00156.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from ..core.diagnostics import Diagnostic
    from .context import Context

CODE = "LIS318"
NAME = "no-reference-signal"
FIX = "none"
PARAMETERS = ("kenngr.ref_ohne_nocken", "kenngr.homing_without_zero_pulse")  # parameters this rule reads
SUMMARY = "Neither reference cam nor zero pulse: nothing marks the reference"

NO_CAM, NO_PULSE = "kenngr.ref_ohne_nocken", "kenngr.homing_without_zero_pulse"


def check(ctx: Context) -> Iterator[Diagnostic]:
    strategy = ctx.strategy
    if (
        strategy.definition.needs_zero_pulse
        and not strategy.setup.zero_pulse
        and ctx.effective(NO_CAM, NO_PULSE)
    ):
        yield ctx.cross(
            CODE,
            f"{ctx.show(NO_CAM)} (no reference cam) and {ctx.show(NO_PULSE)} (no zero pulse): nothing marks the "
            "reference, so homing runs until a limit stops it; reference on the zero pulse or use the cam",
            [NO_PULSE, NO_CAM],
        )

"""
What
----
Referencing on the cam edge without zero pulse (type I,
`homing_without_zero_pulse = 1`), where the speed at which the cam edge is
taken times the CNC cycle time exceeds the required repeatability: `vb_reflow`
in three-phase homing, the approach speed `vb_refmax` in one-phase homing. The
cycle time (default 1000 µs) and the tolerance (default 20 µm on linear axes,
0.01° on rotary axes) are settings (`cycle-time-ms`,
`repeatability-tolerance-um`; the rotary tolerance is an option of the library).

Why
---
Without a latched zero pulse the position is sampled once per cycle, so the
reference can land anywhere within `vb_reflow × cycle time` of the true cam
edge — 200 µm at 6 m/min and 2 ms. The message names the vb_reflow that meets
the tolerance.

Example
-------
```
kenngr.antr_typ                    1          ( conventional drive, cam and reversal
kenngr.homing_without_zero_pulse   1
getriebe[0].vb_refmax              200000
getriebe[0].vb_reflow              100000     ( 6 m/min -> 100 µm per 1 ms cycle
```

Use instead
-----------
```
kenngr.antr_typ                    1
kenngr.homing_without_zero_pulse   1
getriebe[0].vb_refmax              200000
getriebe[0].vb_reflow              20000      ( 1.2 m/min -> 20 µm per cycle
lr_hw[0].cam_direct_access         0          ( cam signal from the PLC
```

Reference
---------
TF5200 homing manual §2 (repeatability with referencing: velocity × sampling time) and §2.3.1.3
(choose vb_reflow so the motor moves about one increment per cycle).
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from ..catalogue.units import describe

if TYPE_CHECKING:
    from ..core.diagnostics import Diagnostic
    from .context import Context

CODE = "LIS403"
NAME = "cam-edge-repeatability"
FIX = "none"
PARAMETERS = (
    "getriebe[i].vb_reflow",
    "getriebe[i].vb_refmax",
    "kenngr.homing_without_zero_pulse",
)  # parameters this rule reads
SUMMARY = "Cam-edge referencing less repeatable than the tolerance"


def check(ctx: Context) -> Iterator[Diagnostic]:
    strategy = ctx.strategy
    values = ctx.values
    member = strategy.definition.reference_speed
    if strategy.manual_type != "I" or member is None:
        return  # referencing on a zero pulse, or no cam edge at all
    cycle = ctx.options.cycle_time_us
    rotary = values.axis_type != "T"
    # Linear: µm/s × s = µm; rotary: 0.001°/s × s = 0.001° (the tolerance is given in degrees).
    tolerance = (
        ctx.options.repeatability_tolerance_deg * 1000 if rotary else ctx.options.repeatability_tolerance_um
    )
    speed_unit = "0.001deg/s" if rotary else "um/s"
    # Shown in µm on a linear axis and in degrees on a rotary one (`0.1°`, never `100 0.001°`).
    scale, unit = (1e-3, "°") if rotary else (1.0, " µm")
    for gear in sorted(set(values.gear_stages_set(member)) | {0}):
        path = f"getriebe[{gear}].{member}"
        if not ctx.effective(path):
            continue
        spread = values.number(path) * cycle / 1e6
        if spread > tolerance:
            best = int(tolerance * 1e6 / cycle)
            yield ctx.cross(
                CODE,
                f"gear stage {gear}: referencing on the cam edge without zero pulse repeats only to about "
                f"{spread * scale:g}{unit} ({ctx.show(path)} × {cycle / 1000:g} ms cycle), more than the tolerance "
                f"{tolerance * scale:g}{unit}; "
                f"{member} ≤ {describe(best, speed_unit)} meets it, or reference on the zero pulse",
                [path, "kenngr.homing_without_zero_pulse"],
            )

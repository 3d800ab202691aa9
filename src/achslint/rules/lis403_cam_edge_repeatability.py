"""
What
----
Referencing on the cam edge without zero pulse (type I,
`homing_without_zero_pulse = 1`) on a linear axis, where the slow homing
speed times the CNC cycle time exceeds the required repeatability. The cycle
time (default 1000 µs) and the tolerance (default 20 µm) are settings
(`cycle-time-us`, `repeatability-tolerance-um`).

Why
---
Without a latched zero pulse the position is sampled once per cycle, so the
reference can land anywhere within `vb_reflow × cycle time` of the true cam
edge — 200 µm at 6 m/min and 2 ms. The message names the vb_reflow that meets
the tolerance.

Example
-------
```
kenngr.homing_without_zero_pulse   1
getriebe[0].vb_reflow              100000     ( 6 m/min -> 100 µm per 1 ms cycle
```

Use instead
-----------
```
getriebe[0].vb_reflow              20000      ( 1.2 m/min -> 20 µm per cycle
```

Reference
---------
TF5200 homing manual §2 (repeatability with referencing: velocity × sampling time) and §2.3.1.3
(choose vb_reflow so the motor moves about one increment per cycle).
"""

from __future__ import annotations

from ..units import describe

CODE = "LIS403"
NAME = "cam-edge-repeatability"
SEVERITY = "warning"
FIX = "none"
PARAMETERS = ("getriebe[i].vb_reflow", "kenngr.homing_without_zero_pulse")  # parameters this rule reads
SUMMARY = "Cam-edge referencing less repeatable than the tolerance"


def check(ctx):
    strategy = ctx.strategy
    values = ctx.values
    if strategy.manual_type != "I" or values.axis_type != "T":
        return
    cycle = ctx.options.cycle_time_us
    tolerance = ctx.options.repeatability_tolerance_um
    for gear in sorted(set(values.gear_stages_set("vb_reflow")) | {0}):
        path = f"getriebe[{gear}].vb_reflow"
        speed = values.get(path)  # µm/s
        spread = speed * cycle / 1e6  # µm
        if spread > tolerance:
            best = int(tolerance * 1e6 / cycle)
            yield ctx.cross(
                CODE,
                f"gear stage {gear}: referencing on the cam edge without zero pulse repeats only to about "
                f"{spread:g} µm ({ctx.show(path)} × {cycle} µs cycle), more than the tolerance {tolerance:g} µm; "
                f"vb_reflow ≤ {describe(best, 'um/s')} meets it, or reference on the zero pulse",
                [path, "kenngr.homing_without_zero_pulse"],
            )

"""
What
----
`kenngr.homing_max_movement_dist` (path monitoring during homing) set to a
value other than 0 on a linear axis, or, on a spindle or a rotary axis that
counts modulo (MODULO bit of `kenngr.achs_mode`), set smaller than the modulo
range (`getriebe[i].moduloo - getriebe[i].modulou`) of a gear stage — on a
spindle that homes with a cam, smaller than two modulo ranges plus
`kenngr.shift_offset_zero_pulse_activation`. A rotary axis in linear mode
(LINEAR, a restricted range) has no modulo range, so no minimum is checked.

Why
---
Path monitoring only works for rotary axes and spindles: on a linear axis the
CNC reports P-ERR-110545 and forces the value to 0. The limit bounds how far
the axis gets from the homing start position before the reference is found
(§2.4.1). On a modulo axis the homing move may need up to a whole revolution
to find the cam; a shorter limit aborts homing with P-ERR-70394 although
nothing is wrong. A spindle with a cam may need a second revolution: after
the cam edge (where flying homing leaves the cam, §2.3.2.1) the zero-pulse
logic is armed, shifted by `shift_offset_zero_pulse_activation` (§2.6), and the
zero pulse may come up to one more revolution later. `achslint dry-run
--sweep` uses the same reading, so a limit this rule accepts does not make
the sweep fail.

Example
-------
```
kenngr.achs_typ                 2          ( rotary axis
kenngr.achs_mode                0x4        ( counting modulo
getriebe[0].moduloo             3600000    ( 360°
kenngr.homing_max_movement_dist 1800000    ( 180°
```

Use instead
-----------
```
kenngr.achs_typ                 2
kenngr.achs_mode                0x4
getriebe[0].moduloo             3600000
kenngr.homing_max_movement_dist 3600000    ( at least one revolution
```

Reference
---------
P-AXIS-00412 (axis types R, S; set at least to the modulo range); TF5200 homing §2.4.1 (path monitoring from
the homing start position), §2.3.2.1, §2.6 (P-AXIS-00494); P-AXIS-00015 (LINEAR / MODULO); CNC messages
P-ERR-110545, P-ERR-70394.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from ..catalogue.units import describe

if TYPE_CHECKING:
    from ..core.diagnostics import Diagnostic
    from .context import Context

CODE = "LIS309"
NAME = "homing-max-movement-dist"
FIX = "none"
PARAMETERS = (
    "kenngr.homing_max_movement_dist",
    "kenngr.achs_typ",
    "kenngr.achs_mode",
    "getriebe[i].moduloo",
    "getriebe[i].modulou",
    "kenngr.shift_offset_zero_pulse_activation",
)  # parameters this rule reads
SUMMARY = "Homing path monitoring on a linear axis or shorter than the modulo range"

DIST = "kenngr.homing_max_movement_dist"
DEGREES = "0.0001deg"  # the list unit of DIST and the modulo limits on rotary axes and spindles


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
    from ..homing import HomingSetup

    limit = values.number(DIST)
    if not limit or values.axis_type == "T" or not ctx.effective(DIST):
        return
    # A spindle homing with a cam: a revolution to the cam edge, the shift, a revolution to the zero pulse.
    twice = values.axis_type == "S" and ctx.strategy.with_cam and ctx.strategy.with_zero_pulse
    shift = "kenngr.shift_offset_zero_pulse_activation"
    for gear in sorted(set(values.gear_stages_set("moduloo", "modulou")) | {0}):
        if HomingSetup(values, gear).modulo is None:
            continue  # a rotary axis in linear mode has no modulo range (the dry-run agrees)
        upper, lower = f"getriebe[{gear}].moduloo", f"getriebe[{gear}].modulou"
        span = values.number(upper) - values.number(lower)
        if twice and limit < 2 * span + values.number(shift):
            need = 2 * span + values.number(shift)
            yield ctx.cross(
                CODE,
                f"gear stage {gear}: {ctx.show(DIST)} is shorter than two modulo ranges plus the zero-pulse shift "
                f"(2 × ({ctx.show(upper)} - {ctx.show(lower)}) + {ctx.show(shift)} = {describe(need, DEGREES)}): the spindle may turn "
                "up to a revolution to the cam edge and, after the shift, up to another revolution to its zero "
                f"pulse (§2.3.2.1, §2.6), so homing could abort with P-ERR-70394; use at least {describe(need, None)}",
                [DIST, upper, lower, shift],
            )
        elif limit < span:
            yield ctx.cross(
                CODE,
                f"gear stage {gear}: {ctx.show(DIST)} is shorter than the modulo range ({ctx.show(upper)} - "
                f"{ctx.show(lower)} = {describe(span, DEGREES)}); homing may need a full revolution and would abort "
                f"with P-ERR-70394; use at least {describe(span, None)}",
                [DIST, upper, lower],
            )

"""
What
----
Homing on the encoder overflow (`kenngr.homing_overflow_evaluation = 1`)
configured so it cannot work: together with `homing_without_zero_pulse = 1`,
without `antr.encoder_bit_range` (the number of encoder bits whose overflow
marks the reference), or with `antr.encoder_overflow_offset` beyond one
encoder revolution (2^bits increments).

Why
---
The overflow takes the place of the zero pulse, so the sequence must be the
zero-pulse variant, and the CNC must know after how many bits the position
wraps. An offset larger than one revolution is rejected and reset to 0.

Example
-------
```
kenngr.homing_overflow_evaluation   1
kenngr.homing_without_zero_pulse    1
```

Use instead
-----------
```
kenngr.homing_overflow_evaluation   1
kenngr.homing_without_zero_pulse    0
antr.encoder_bit_range              20
```

Reference
---------
TF5200 homing manual §3.1.1.2 (CNC-controlled at encoder overflow); P-AXIS-00294, P-AXIS-00354, P-AXIS-00355
(offset within one revolution, else reset to 0; the manual names error 70310).
"""

from __future__ import annotations

from ..units import describe

CODE = "LIS311"
NAME = "encoder-overflow"
SEVERITY = "error"
FIX = "none"
PARAMETERS = ("kenngr.homing_overflow_evaluation", "kenngr.homing_without_zero_pulse", "antr.encoder_bit_range", "antr.encoder_overflow_offset")  # parameters this rule reads
SUMMARY = "Encoder-overflow homing that cannot work"

SELECT, NO_PULSE = "kenngr.homing_overflow_evaluation", "kenngr.homing_without_zero_pulse"
BITS, OFFSET = "antr.encoder_bit_range", "antr.encoder_overflow_offset"


def check(ctx):
    values = ctx.values
    if not values.get(SELECT):
        return
    if values.get(NO_PULSE):
        yield ctx.cross(
            CODE,
            f"{ctx.show(SELECT)} needs {NO_PULSE} = 0 (the overflow replaces the zero pulse), but {ctx.show(NO_PULSE)}",
            [SELECT, NO_PULSE],
        )
    bits = values.get(BITS)
    if not bits:
        yield ctx.cross(
            CODE,
            f"{ctx.show(SELECT)} but {ctx.show(BITS)}: set the number of encoder bits (1..31) whose overflow marks the reference",
            [SELECT, BITS],
        )
        return
    numerator, denominator = values.get("getriebe[0].wegaufz"), values.get("getriebe[0].wegaufn")
    revolution = (2**bits) * denominator / numerator if numerator else None  # in 0.1 µm / 0.0001°
    offset = values.get(OFFSET)
    if revolution and abs(offset) >= revolution:
        yield ctx.cross(
            CODE,
            f"{ctx.show(OFFSET)} is beyond one encoder revolution (2^{bits} increments = "
            f"{describe(revolution, values.parameter(OFFSET).unit(values.axis_type))} with getriebe[0].wegaufz/wegaufn); "
            "the CNC resets it to 0",
            [OFFSET, BITS],
        )

"""
What
----
Homing on the encoder overflow (`kenngr.homing_overflow_evaluation = 1`)
configured so it cannot work: together with `homing_without_zero_pulse = 1`,
without `antr.encoder_bit_range` (the number of encoder bits whose overflow
marks the reference), with `antr.encoder_overflow_offset` beyond one encoder
revolution (2^bits increments), or on a drive type without encoder-overflow
homing (only SERCOS, Lightbus and CANopen have it).

Why
---
The overflow takes the place of the zero pulse, so the sequence must be the
zero-pulse variant, and the CNC must know after how many bits the position
wraps. An offset larger than one revolution is reset to 0 (P-ERR-70310); on
other drive types the CNC switches the method off (P-ERR-110416). Both
corrections are applied before `explain` and `dry-run` describe the axis.

Example
-------
```
kenngr.antr_typ                     8          ( CANopen
kenngr.homing_overflow_evaluation   1
kenngr.homing_without_zero_pulse    1
antr.encoder_bit_range              20
```

Use instead
-----------
```
kenngr.antr_typ                     8
kenngr.homing_overflow_evaluation   1
kenngr.homing_without_zero_pulse    0
antr.encoder_bit_range              20
```

Reference
---------
TF5200 homing manual §3.1.1.2 (CNC-controlled at encoder overflow); P-AXIS-00294, P-AXIS-00354, P-AXIS-00355
(offset within one revolution, else reset to 0; the manual names error 70310); P-ERR-110416.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from ..core.diagnostics import Diagnostic
    from .context import Context

CODE = "LIS311"
NAME = "encoder-overflow"
FIX = "none"
PARAMETERS = (
    "kenngr.homing_overflow_evaluation",
    "kenngr.homing_without_zero_pulse",
    "antr.encoder_bit_range",
    "antr.encoder_overflow_offset",
)  # parameters this rule reads
SUMMARY = "Encoder-overflow homing that cannot work"

SELECT, NO_PULSE = "kenngr.homing_overflow_evaluation", "kenngr.homing_without_zero_pulse"
BITS, OFFSET = "antr.encoder_bit_range", "antr.encoder_overflow_offset"


def check(ctx: Context) -> Iterator[Diagnostic]:
    values = ctx.values
    switched_off = ctx.correction(SELECT)
    if switched_off is not None:
        yield ctx.report_correction(CODE, switched_off, ctx.show(SELECT), [SELECT, "kenngr.antr_typ"])
        return
    if not values.get(SELECT) or not ctx.effective(SELECT):
        return
    if values.get(NO_PULSE):
        yield ctx.cross(
            CODE,
            f"{ctx.show(SELECT)} needs {NO_PULSE} = 0 (the overflow replaces the zero pulse), but {ctx.show(NO_PULSE)}",
            [SELECT, NO_PULSE],
        )
    if not values.get(BITS):
        yield ctx.cross(
            CODE,
            f"{ctx.show(SELECT)} but {ctx.show(BITS)}: set the number of encoder bits (1..31) whose overflow marks the reference",
            [SELECT, BITS],
        )
        return
    reset = ctx.correction(OFFSET)
    if reset is not None:
        yield ctx.report_correction(CODE, reset, ctx.show(OFFSET), [OFFSET, BITS])

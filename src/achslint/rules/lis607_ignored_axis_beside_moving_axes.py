"""
What
----
A `G74` block names an axis with homing type `IGNORE_ABS_POS` together with axes
that really home (CNC- or drive-controlled).

Why
---
An `IGNORE_ABS_POS` axis is passed over by G74: it stays exactly where it is
while the other axes of the block drive to their cams and reference marks. The
CNC does not check whether their paths cross it. The homing manual therefore
asks for the machine to be arranged so that no collision can happen; this
warning marks each block where that has to be checked.

Example
-------
```
# file: hochlauf.lis
achs_mds[0]           achsmds1.lis
achs_mds[1]           achsmds2.lis
Ende
```
```
# file: achsmds1.lis
kopf.achs_nr          1
kopf.log_achs_name    X
Ende
```
```
# file: achsmds2.lis
kopf.achs_nr                 2
kopf.log_achs_name           B
kenngr.achs_typ              2
kenngr.antr_typ              8
kenngr.abs_pos_gueltig       1
kenngr.homing.homing_type    IGNORE_ABS_POS
Ende
```
```
; file: rfp.nc
N10 G74 X1 B1         (B stands still while X searches its cam)
N20 M30
```

Use instead
-----------
On the same machine, this program:
```
; file: rfp.nc
N10 G74 X1            (B has an absolute encoder: it needs no G74)
N20 M30
```

Reference
---------
P-AXIS-00299 (homing_type IGNORE_ABS_POS; the remark on G74 blocks with mixed
homing types), P-AXIS-00014.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from ..core.diagnostics import Diagnostic, Severity

if TYPE_CHECKING:
    from ..machine.model import ChannelView, Program

CODE = "LIS607"
NAME = "ignored-axis-beside-moving-axes"
FIX = "none"
SUMMARY = "IGNORE_ABS_POS axis in a G74 block where other axes move"

_STILL = ("IGNORE_ABS_POS", "DISABLED")


def check_program(program: Program, machine: ChannelView) -> Iterator[Diagnostic]:
    from .programcontext import diagnostic, g74_words

    for words in g74_words(program):  # a G74 whose homing order is computed names its axes too
        named = [(word, machine.axes.get(word.name)) for word in words]
        moving = sorted(
            {axis.name for _, axis in named if axis is not None and axis.resolved.homing_type not in _STILL}
        )
        if not moving:
            continue
        for word, axis in named:
            if axis is None or axis.resolved.homing_type != "IGNORE_ABS_POS":
                continue
            yield diagnostic(
                CODE,
                word.at,
                f"{word.name} is not homed (IGNORE_ABS_POS) and stands still while {', '.join(moving)} "
                f"{'moves' if len(moving) == 1 else 'move'} to {'its' if len(moving) == 1 else 'their'} "
                f"reference in this block; make sure nothing on their way can hit {word.name} "
                "(P-AXIS-00299)",
                Severity.WARNING,
                parameter="kenngr.homing.homing_type",
                p_axis="P-AXIS-00299",
            )

"""
What
----
A move block (`G00` / `G01`) commands an axis that no earlier `G74` block has
homed, and whose position is not known from an absolute encoder either. A move
to a computed position (`Z[P1]`) counts too. After a part of the program that
achslint does not follow, an axis that part may have homed is not reported: a
subroutine or macro call may home any axis, a loop or a jump (`$FOR`, `$GOTO`)
may run any G74 of the program first; a branch (`$IF`) homes nothing that no
G74 above the move names.

Why
---
Until an axis is homed its position is a guess, and the CNC does not monitor
its software limit switches. A move such as `G01 G90 Z200` to a safe height then
goes 200 mm from wherever the axis happens to stand — possibly into the end
stop or the workpiece.

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
kopf.achs_nr          2
kopf.log_achs_name    Z
Ende
```
```
; file: rfp.nc
N10 G74 X1
N15 G01 G90 Z200 F500  (Z is not homed yet)
N20 G74 Z1
N30 M30
```

Use instead
-----------
On the same machine, this program:
```
; file: rfp.nc
N10 G74 Z1
N15 G01 G90 Z200 F500  (Z is homed: its limits are watched)
N20 G74 X1
N30 M30
```

Reference
---------
TF5200 homing manual §2.2 (after homing, axes can be positioned within the
software limit switches); P-AXIS-00177 / P-AXIS-00178 (software limits),
P-AXIS-00014 (absolute encoder: no homing needed).
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from ..core.diagnostics import Diagnostic, Severity

if TYPE_CHECKING:
    from ..machine.model import ChannelView, Program

CODE = "LIS606"
NAME = "move-before-homing"
FIX = "none"
SUMMARY = "Move of an axis that is not homed yet"


def check_program(program: Program, machine: ChannelView) -> Iterator[Diagnostic]:
    from ..machine.model import MoveBlock, SkippedBlock
    from .programcontext import diagnostic, steps

    for step in steps(program, machine):
        block = step.block
        if isinstance(block, MoveBlock):
            moves = [
                (word.name, word.at, f"{'to' if block.absolute else 'by'} {word.value:g}")
                for word in block.targets
            ]
        elif isinstance(block, SkippedBlock):  # a move the reader does not simulate (a computed position)
            moves = [(word.name, word.at, f"({word.written})") for word in block.moves]
        else:
            continue
        for name, at, how in moves:
            if name not in machine.axes or not step.unhomed(name):
                continue
            yield diagnostic(
                CODE,
                at,
                f"{name} is not homed yet when this block moves it {how}: its position "
                "is not known and its software limits are not monitored; home it in an earlier G74 block",
                Severity.WARNING,
            )

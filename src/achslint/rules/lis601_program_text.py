"""
What
----
A homing program whose text the CNC cannot run as written: a comment opened
with `(` and not closed on its line, `G74` without an axis, a homing order that
is not a whole number from 1 up (`X0`, `Y-1`, `Z1.5`, `A99999`), an address
without a number, a `G01` with no feed rate programmed before it, a file that
is not text at all, or a parameter list (an axis or start-up list) given in
place of the program (one finding for the whole file).

Why
---
The CNC stops the program at the first block it cannot decode, so the machine
is left half homed; a typing slip in the homing order is worse, because the axes
home in an order nobody chose. Every later check of the program (unknown names,
the homing order) rests on reading the blocks the way the CNC reads them.

Example
-------
```
# file: hochlauf.lis
achs_mds[0]           achsmds1.lis
Ende
```
```
# file: achsmds1.lis
kopf.achs_nr          1
kopf.log_achs_name    X
Ende
```
```
; file: rfp.nc
N10 G74 X0            (the order starts at 1
N20 M30
```

Use instead
-----------
On the same machine, this program:
```
; file: rfp.nc
N10 G74 X1            (the order starts at 1)
N20 M30
```

Reference
---------
TF5200 homing manual §2.2 (G74: the values after the axis names give the
homing order; equal values home together).
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from ..core.diagnostics import Diagnostic, Severity

if TYPE_CHECKING:
    from ..machine.model import ChannelView, Program

CODE = "LIS601"
NAME = "program-text"
FIX = "none"
SUMMARY = "Homing program text the CNC cannot run as written"


def check_program(program: Program, machine: ChannelView) -> Iterator[Diagnostic]:
    from .programcontext import diagnostic

    for problem in program.problems:
        yield diagnostic(CODE, problem.at, problem.message, Severity.ERROR)

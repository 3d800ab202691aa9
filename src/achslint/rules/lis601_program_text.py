"""
What
----
A homing program whose text the CNC cannot run as written: `G74` without an
axis, a homing order that
is not a whole number from 1 up (`X0`, `Y-1`, `Z1.5`, `A99999`), an address
without a value, a `[` without its `]` (`X[P1*2`) or brackets with nothing in
them (`X[]`), an assignment with nothing after `=` (`P1 =`), a call that names
no subroutine (`L`), a `"` not closed on its line, a `G01` with no feed rate
programmed before it, a file that is not text at all, or a parameter list (an
axis or start-up list) given in place of the program (one finding for the whole
file).

What the ISG decoder reads is no finding, even where achslint does not follow
it: values computed in brackets (`X[-2*P1+3]`, `X P1*SIN[P2*30]`, `Y2=[P1]`),
parameters and variables (`P1 = P2 + P3 * [P4 - 1]`, `PP1 = 50`,
`V.P.NAME = 5`), macros (`"NAME" = "5 * 12"`), subroutine calls (`L name`,
`LL name`, local subroutines `%L name`), control statements (`$IF`, `$FOR`,
`$GOTO`, …), `#` commands, nested comments and a comment left open with `(`
(it runs to the end of its block). The dry-run and `explain` pass
over such blocks and say why; after a call or a control statement they no
longer claim which axes are homed (nor does LIS606).

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
N10 G74 X0                 (the order starts at 1)
N15 P1 = 50
N20 G01 G90 X[P1*2 F500    (the bracket is not closed)
N30 M30
```

Use instead
-----------
On the same machine, this program:
```
; file: rfp.nc
N10 G74 X1
N15 P1 = 50
N20 G01 G90 X[P1*2] F500
N30 M30
```

Reference
---------
TF5200 homing manual §2.2 (G74: the values after the axis names give the
homing order; equal values home together). TF5200 programming manual:
"Structure of NC control data: NC programs" (separators, comments,
mathematical expressions), "Block-specific comments" (nested comments),
"Arithmetical expressions <expr>" (square brackets, functions, macros in
expressions), "Parameters and parameter calculation (P)", "Indirect
parameters", "Programming of coordinates by parameters" (`X P1*SIN[P2*30]`),
"Local subroutines (Call LL <string>)", "Global subroutines (Call L
<string>)", "Control block statements ($..)".
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

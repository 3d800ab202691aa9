"""
What
----
One `G74` block names the same axis twice (`G74 X1 Y1 X2`).

Why
---
An axis is homed once per command; the second mention either repeats the first
or gives it a second, contradicting place in the homing order. The block is an
error: the program stops there and nothing of it is homed, which is what
`explain --program` and the machine dry-run show for it as well.

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
kopf.log_achs_name    Y
Ende
```
```
; file: rfp.nc
N10 G74 X1 Y1 X2
N20 M30
```

Use instead
-----------
On the same machine, this program:
```
; file: rfp.nc
N10 G74 Y1 X2
N20 M30
```

Reference
---------
TF5200 homing manual §2.2 (the homing order of G74).
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from ..core.diagnostics import Diagnostic, Related, Severity

if TYPE_CHECKING:
    from ..machine.model import AxisWord, ChannelView, NamedAxis, Program

CODE = "LIS603"
NAME = "axis-twice-in-g74"
FIX = "none"
SUMMARY = "G74 names the same axis twice"


def check_program(program: Program, machine: ChannelView) -> Iterator[Diagnostic]:
    from ..machine.model import AxisWord
    from .programcontext import diagnostic, g74_words

    for words in g74_words(program):  # a G74 whose homing order is computed names its axes too
        first: dict[str, AxisWord | NamedAxis] = {}
        for word in words:
            earlier = first.setdefault(word.name, word)
            if earlier is word:
                continue
            orders = (
                (int(earlier.value), int(word.value))
                if isinstance(earlier, AxisWord) and isinstance(word, AxisWord)
                else None
            )
            yield diagnostic(
                CODE,
                word.at,
                f"{word.name} is named a second time in this G74 block"
                + (
                    ""
                    if orders is None or orders[0] == orders[1]
                    else f" (homing order {orders[1]} after {orders[0]})"
                )
                + ", so the CNC stops the program at this block: name it once",
                Severity.ERROR,
                (Related(earlier.at.path, earlier.at.line, earlier.at.column, None, "first named here"),),
            )

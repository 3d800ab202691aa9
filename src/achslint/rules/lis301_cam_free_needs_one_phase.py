"""
What
----
`kenngr.ref_ohne_nocken = 1` (no reference cam) while `kenngr.ref_ohne_rev`
is 0 (homing with reversal).

Why
---
Applies to the CNC-controlled sequences (with a drive-controlled or absolute
axis these parameters are not read, LIS401). Reversing at the cam needs a cam signal; without a cam the sequence can only
run in one phase. The manual calls this combination impermissible: when
P-AXIS-00156 is 1, P-AXIS-00157 must be 1 as well.

Example
-------
```
kenngr.antr_typ                 1          ( conventional drive
kenngr.ref_ohne_nocken          1
kenngr.ref_ohne_rev             0
```

Use instead
-----------
```
kenngr.antr_typ                 1
kenngr.ref_ohne_nocken          1
kenngr.ref_ohne_rev             1
```

Reference
---------
TF5200 homing manual §2.3.2 (table of homing types) and P-AXIS-00156 / P-AXIS-00157 remarks.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from ..core.diagnostics import Diagnostic
    from .context import Context

CODE = "LIS301"
NAME = "cam-free-needs-one-phase"
FIX = "none"
PARAMETERS = ("kenngr.ref_ohne_nocken", "kenngr.ref_ohne_rev")  # parameters this rule reads
SUMMARY = "`ref_ohne_nocken = 1` requires `ref_ohne_rev = 1`"


def check(ctx: Context) -> Iterator[Diagnostic]:
    values = ctx.values
    paths = ("kenngr.ref_ohne_nocken", "kenngr.ref_ohne_rev")
    if values.get(paths[0]) and not values.get(paths[1]) and ctx.effective(*paths):
        yield ctx.cross(
            CODE,
            f"{ctx.show('kenngr.ref_ohne_nocken')} (no reference cam) requires kenngr.ref_ohne_rev = 1, but "
            f"{ctx.show('kenngr.ref_ohne_rev')}: without a cam the axis cannot reverse at it; set kenngr.ref_ohne_rev 1",
            ["kenngr.ref_ohne_nocken", "kenngr.ref_ohne_rev"],
        )

"""
What
----
CNC-controlled homing of a real (not simulated) linear or rotary axis with no
homing acceleration (`getriebe[i].a_ref` not
set or 0). The message reports the value the CNC uses instead: the smaller of
the two rapid-traverse accelerations of the linear slope,
`lslope_profil.a_grenz_stufe_1` and `a_grenz_stufe_2`.

Why
---
Nothing is wrong, but the homing moves then accelerate with a value that was
tuned for rapid traverse, which is easy to overlook when the braking distance
after the reference event matters (the axis stops that far beyond the
reference position).

Example
-------
```
kenngr.antr_typ                             1          ( conventional drive
getriebe[0].lslope_profil.a_grenz_stufe_1   2000
getriebe[0].lslope_profil.a_grenz_stufe_2   1000
```

Use instead
-----------
```
kenngr.antr_typ                             1
getriebe[0].a_ref                           500
lr_hw[0].cam_direct_access                  0          ( cam signal from the PLC
```

Reference
---------
TF5200 homing manual §3.2.4 (homing acceleration P-AXIS-00285, fallback min(P-AXIS-00005, P-AXIS-00006)).
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from ..core.diagnostics import Diagnostic
    from .context import Context

CODE = "LIS404"
NAME = "homing-acceleration-fallback"
FIX = "none"
PARAMETERS = (
    "getriebe[i].a_ref",
    "getriebe[i].lslope_profil.a_grenz_stufe_1",
    "getriebe[i].lslope_profil.a_grenz_stufe_2",
)  # parameters this rule reads
SUMMARY = "Homing acceleration not set: the CNC's fallback is used"


def check(ctx: Context) -> Iterator[Diagnostic]:
    strategy = ctx.strategy
    # Where a_ref takes effect on a real axis: a simulated drive has no mechanics that brake.
    if not strategy.moves or strategy.setup.simulated or not ctx.effective("getriebe[0].a_ref"):
        return
    acceleration = strategy.setup.acceleration
    if acceleration.fallback:
        one, two = "getriebe[0].lslope_profil.a_grenz_stufe_1", "getriebe[0].lslope_profil.a_grenz_stufe_2"
        yield ctx.cross(
            CODE,
            f"`getriebe[0].a_ref` is not set: homing accelerates with min({ctx.show(one)}, {ctx.show(two)}) = "
            f"{acceleration.value:g} {'mm/s²' if ctx.values.axis_type == 'T' else '°/s²'}; set a_ref to choose it",
            ["getriebe[0].a_ref", one, two],
        )

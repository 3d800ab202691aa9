"""
What
----
CNC-controlled homing in one phase with a reference cam
(`kenngr.ref_ohne_rev = 1`, `kenngr.ref_ohne_nocken = 0`) on a linear or
rotary axis.

Why
---
The manual offers this variant but advises against it in practice: the single
phase never reverses, so an axis that starts on the cam (after a power failure
or an emergency stop) references at the wrong place. The PLC has to prevent
starting on the cam. Three-phase homing handles that case by itself.

Example
-------
```
kenngr.antr_typ                 1          ( conventional drive
kenngr.ref_ohne_nocken          0
kenngr.ref_ohne_rev             1
```

Use instead
-----------
```
kenngr.antr_typ                 1
kenngr.ref_ohne_nocken          0
kenngr.ref_ohne_rev             0
lr_hw[0].cam_direct_access      0          ( cam signal from the PLC
```

Reference
---------
TF5200 homing manual §2.3.3.2 (notice on referencing in one phase).
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from ..core.diagnostics import Diagnostic
    from ..homing.motion import StartOnCam
    from .context import Context

CODE = "LIS402"
NAME = "one-phase-with-cam"
FIX = "none"
PARAMETERS = ("kenngr.ref_ohne_rev", "kenngr.ref_ohne_nocken")  # parameters this rule reads
SUMMARY = "One-phase homing with a cam (advised against by the manual)"


def start_on_cam(fact: StartOnCam) -> str:
    """What the dry-run reports when such an axis starts on the cam (where it stood: `fact.position`)."""
    return "the axis starts on the reference cam: one-phase homing references without leaving it, at the wrong place"


def check(ctx: Context) -> Iterator[Diagnostic]:
    strategy = ctx.strategy
    # One phase with a cam that never reverses (a flying spindle turns on until it leaves the cam instead).
    if strategy.one_phase and strategy.with_cam and not strategy.definition.flying:
        yield ctx.cross(
            CODE,
            "one-phase homing with a reference cam (ref_ohne_rev 1, ref_ohne_nocken 0): the axis must never start on "
            "the cam, which the PLC has to ensure; the manual advises against this variant, prefer three-phase "
            "homing (ref_ohne_rev 0)",
            ["kenngr.ref_ohne_rev", "kenngr.ref_ohne_nocken"],
        )

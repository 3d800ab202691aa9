"""
What
----
`kenngr.gantry_slave_no_homing = 1` on a spindle; and, when a whole machine is
linted, a gantry master homing to a fixed stop whose retraction distance
(`kenngr.homing.torq_retraction_distance`) is not larger than the slave's
resettable distance (`kenngr.gantry_max_diff_resetable`).

Why
---
Suppressing the slave's homing is a gantry function for linear and rotary
axes; the parameter is not supported for spindles. After the fixed stop the
master must retract further than the slave may deviate, or the gantry
difference cannot be cleared; the CNC raises the resettable distance to the
retraction distance with warning P-ERR-70651.

Example
-------
```
kenngr.achs_typ                   4
kenngr.gantry_slave_no_homing     1
```

Use instead
-----------
Remove `kenngr.gantry_slave_no_homing` from the spindle's list; it belongs in
the list of a linear or rotary gantry slave:

```
kenngr.achs_typ                   1          ( linear axis
kenngr.gantry_ax_nr               1          ( slave of the axis with kopf.achs_nr 1
kenngr.gantry_slave_no_homing     1
```

Reference
---------
P-AXIS-00074 (axis types T, R; not supported for spindles); TF5200 homing manual §2.3.3.4.5
(retraction vs resettable distance, P-ERR-70651).
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING, Any

from ..catalogue.units import describe
from ..core.diagnostics import Diagnostic, Related, Severity
from ..machine.startup import diagnostic

if TYPE_CHECKING:
    from ..machine.resolved import Machine
    from .context import Context

CODE = "LIS316"
NAME = "gantry-slave-no-homing"
FIX = "none"
PARAMETERS = (
    "kenngr.gantry_slave_no_homing",
    "kenngr.homing.torq_retraction_distance",
    "kenngr.gantry_max_diff_resetable",
)  # parameters this rule reads
SUMMARY = "Gantry slave homing suppression on a spindle"


def check(ctx: Context) -> Iterator[Diagnostic]:
    values = ctx.values
    if values.get("kenngr.gantry_slave_no_homing") and values.axis_type == "S":
        yield ctx.cross(
            CODE,
            f"{ctx.show('kenngr.gantry_slave_no_homing')} is not supported for spindles (kenngr.achs_typ 4); remove it",
            ["kenngr.gantry_slave_no_homing", "kenngr.achs_typ"],
        )


def check_machine(machine: Machine) -> Iterator[Diagnostic]:
    members = machine.numbered()  # not by a template number TwinCAT repeats in every export
    by_number = {info["achs_nr"]: (name, info) for name, info in members}
    for name, info in members:
        master = by_number.get(info["gantry_ax_nr"]) if info["gantry_ax_nr"] else None
        if master is None or not master[1]["torq"] or master[1]["retraction"] > info["resettable"]:
            continue
        line, column = master[1].get("achs_nr_at") or (1, 1)
        yield diagnostic(
            CODE,
            (name, info),
            "gantry_at",
            f"the gantry master {master[0]} retracts {_length(master[1]['retraction'], master[1])} after its fixed "
            f"stop, not more than this slave's kenngr.gantry_max_diff_resetable {_length(info['resettable'], info)}; "
            "the CNC raises the resettable distance to the retraction distance (P-ERR-70651)",
            Severity.ERROR,
            [Related(master[0], line, column, "kenngr.homing.torq_retraction_distance", "master")],
        )


def _length(value: object, info: dict[str, Any]) -> str:
    return describe(value, "0.0001deg" if info.get("axis_type", "T") != "T" else "0.1um")

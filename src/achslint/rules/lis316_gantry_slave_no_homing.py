"""
What
----
`kenngr.gantry_slave_no_homing = 1` on a spindle. (The machine-level part of
this rule — the master's retraction distance against the slave's resettable
distance, P-ERR-70651 — needs both axis lists and is checked when a whole
machine is linted.)

Why
---
Suppressing the slave's homing is a gantry function for linear and rotary
axes; the parameter is not supported for spindles.

Example
-------
```
kenngr.achs_typ                   4
kenngr.gantry_slave_no_homing     1
```

Use instead
-----------
Remove `kenngr.gantry_slave_no_homing` from the spindle's list.

Reference
---------
P-AXIS-00074 (axis types T, R; not supported for spindles); TF5200 homing manual §2.3.3.4.5.
"""

from __future__ import annotations

CODE = "LIS316"
NAME = "gantry-slave-no-homing"
SEVERITY = "error"
FIX = "none"
PARAMETERS = ("kenngr.gantry_slave_no_homing",)  # parameters this rule reads
SUMMARY = "Gantry slave homing suppression on a spindle"


def check(ctx):
    values = ctx.values
    if values.get("kenngr.gantry_slave_no_homing") and values.axis_type == "S":
        yield ctx.cross(
            CODE,
            f"{ctx.show('kenngr.gantry_slave_no_homing')} is not supported for spindles (kenngr.achs_typ 4); remove it",
            ["kenngr.gantry_slave_no_homing", "kenngr.achs_typ"],
        )

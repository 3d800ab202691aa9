"""
What
----
A number outside the range the parameter accepts: outside its data type
(a negative value for an unsigned parameter, 300 for UNS08) or outside the
literal bounds the manual gives (`encoder_bit_range` 1..31,
`torq_detect_velocity_limit` 0..1000 per mille), or not one of the listed codes
(`kenngr.antr_typ`).

Bounds that depend on other parameters (such as vb_refmax ≤ vb_max) are checked
by the cross-parameter rules, not here. A parameter's documented default is
always accepted, because several parameters use an out-of-range default
(0 or -1) to mean "not set".

Why
---
The CNC corrects or rejects out-of-range values while it reads the list, with
a warning that is easy to miss; the axis then runs with a value nobody wrote.

Example
-------
```
antr.encoder_bit_range                    40
kenngr.homing.torq_detect_velocity_limit  1500
```

Use instead
-----------
```
antr.encoder_bit_range                    20
kenngr.homing.torq_detect_velocity_limit  500
```

Reference
---------
Value ranges of the P-AXIS parameter pages (catalogue `range`); P-AXIS-00355, P-AXIS-00347.
"""

from __future__ import annotations

from ._common import value_problems

CODE = "LIS202"
NAME = "out-of-range"
SEVERITY = "error"
FIX = "none"
SUMMARY = "Value outside the parameter's range"


def check(ctx):
    yield from value_problems(ctx, CODE)

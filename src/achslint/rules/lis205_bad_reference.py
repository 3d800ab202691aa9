"""
What
----
A parameter reference (`P-AXIS-00212.0`, "take the value of that parameter")
that names a parameter that does not exist, names the parameter itself, names a
parameter of another kind (text for a number) or with another unit, or uses an
index outside the target's array.

Why
---
The CNC cannot resolve such a reference while it reads the list (loader errors
2049, 2051, 2052, 2062, 2065) and the parameter keeps its default.

Example
-------
```
handbetrieb.hb.vb_max          P-AXIS-00008.0
getriebe[0].vb_reflow          P-AXIS-00218.0
```

Use instead
-----------
```
handbetrieb.hb.vb_max          P-AXIS-00212.0
getriebe[0].vb_reflow          20000
```

Reference
---------
List format facts §6 (parameter references and their loader errors).
"""

from __future__ import annotations

from ._common import value_problems

CODE = "LIS205"
NAME = "bad-reference"
SEVERITY = "error"
FIX = "none"
SUMMARY = "Parameter reference that cannot be resolved"


def check(ctx):
    yield from value_problems(ctx, CODE)

"""
What
----
A value of the wrong type: text or a real number for an integer parameter,
anything but 0/1 for a BOOLEAN, a number for a real parameter written as text,
or no value at all for a parameter that needs a number.

Why
---
The CNC rejects the value when it reads the list (the parameter keeps its
previous value) or, worse, truncates it. `2` for a BOOLEAN is not "more on";
`1.5` for a UNS32 loses its fraction.

Example
-------
```
kenngr.ref_richt                 2
getriebe[0].vb_refmax            100000.5
kenngr.fast_from_cam             yes
```

Use instead
-----------
```
kenngr.ref_richt                 1
getriebe[0].vb_refmax            100000
kenngr.fast_from_cam             1
```

Reference
---------
Data types of the catalogue (P-AXIS parameter pages); BOOLEAN is 0/1 (axis parameter manual, data types).
"""

from __future__ import annotations

from ._common import value_problems

CODE = "LIS201"
NAME = "wrong-type"
SEVERITY = "error"
FIX = "sometimes"
SUMMARY = "Value of the wrong data type"


def check(ctx):
    yield from value_problems(ctx, CODE, fix_applicability="unsafe")

"""
What
----
A symbolic value that the parameter does not know, for example a misspelt
homing type. The message names the closest accepted symbol.

Why
---
An unknown symbol is rejected when the list is read and the parameter keeps
its default, which for `kenngr.homing.homing_type` means a different homing
strategy than the one you configured.

Example
-------
```
kenngr.homing.homing_type      DRIVE_CONROLLED
```

Use instead
-----------
```
kenngr.homing.homing_type      DRIVE_CONTROLLED
```

Reference
---------
P-AXIS-00299 value table; documented inconsistency B.14 (`DRIVE_CONROLLED` is a typo in the manual).
"""

from __future__ import annotations

from ._common import value_problems

CODE = "LIS203"
NAME = "unknown-symbol"
SEVERITY = "error"
FIX = "sometimes"
SUMMARY = "Unknown symbol for an enumerated parameter"


def check(ctx):
    yield from value_problems(ctx, CODE, fix_applicability="safe")

"""
What
----
Two axis lists of the same machine use the same axis name
`kopf.log_achs_name`.

Why
---
Programs address axes by name (`G01 X…`); two axes with one name make the
channel configuration ambiguous, and the second one is not reachable under
the name you expect.

Example
-------
```
# file: achsmds1.lis
kopf.achs_nr          1
kopf.log_achs_name    X
```

```
# file: achsmds3.lis
kopf.achs_nr          3
kopf.log_achs_name    X          ( copied from achsmds1.lis
```

Use instead
-----------
With achsmds1.lis as it is, give achsmds3.lis its own name:

```
# file: achsmds3.lis
kopf.achs_nr          3
kopf.log_achs_name    Z
```

Reference
---------
P-AXIS-00297 (default axis name).
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from ..core.diagnostics import Diagnostic
from ..machine.startup import Startup, repeated_values

if TYPE_CHECKING:
    from ..machine.startup import Member

CODE = "LIS502"
NAME = "duplicate-axis-name"
FIX = "none"
PARAMETERS = ("kopf.log_achs_name",)  # parameters this rule reads
SUMMARY = "Two axis lists of a machine with the same axis name"


def check_machine(members: list[Member], startups: list[Startup]) -> Iterator[Diagnostic]:
    yield from repeated_values(
        CODE,
        members,
        "name",
        "kopf.log_achs_name",
        lambda name, note, first: (
            f"axis name kopf.log_achs_name `{name}`{note} is also used by {first}; give each axis its own name"
        ),
    )

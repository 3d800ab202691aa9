"""
What
----
Two axis lists of the same machine use the same logical axis number
`kopf.achs_nr`. A machine is the lists of one start-up list (`hochlauf.lis`,
`achs_mds[i]`) or, without one, the `achsmds*.lis` of one folder.

Why
---
The logical axis number identifies the axis everywhere in the CNC (channel
assignment, gantry coupling, PLC interface). Two lists with the same number
usually come from copying a list and forgetting to renumber it: one axis then
silently takes over the other's parameters.

Example
-------
```
# file: achsmds1.lis
kopf.achs_nr          1
kopf.log_achs_name    X
```

```
# file: achsmds2.lis
kopf.achs_nr          1          ( copied from achsmds1.lis
kopf.log_achs_name    Y
```

Use instead
-----------
With achsmds1.lis as it is, give achsmds2.lis its own number:

```
# file: achsmds2.lis
kopf.achs_nr          2
kopf.log_achs_name    Y
```

Reference
---------
P-AXIS-00016 (logical axis number, unique per machine).
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from ..core.diagnostics import Diagnostic
from ..machine.startup import Startup, repeated_values

if TYPE_CHECKING:
    from ..machine.startup import Member

CODE = "LIS501"
NAME = "duplicate-axis-number"
FIX = "none"
PARAMETERS = ("kopf.achs_nr",)  # parameters this rule reads
SUMMARY = "Two axis lists of a machine with the same logical axis number"


def check_machine(members: list[Member], startups: list[Startup]) -> Iterator[Diagnostic]:
    yield from repeated_values(
        CODE,
        members,
        "achs_nr",
        "kopf.achs_nr",
        lambda number, note, first: (
            f"logical axis number kopf.achs_nr {number}{note} is also used by {first}; "
            "every axis of a machine needs its own"
        ),
    )

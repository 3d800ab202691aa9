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
```
# file: achsmds1.lis
kopf.achs_nr          1
kopf.log_achs_name    X
```

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

from ..diagnostics import Diagnostic, Related, Severity
from ..machine import Startup, diagnostic, first_uses, unset_note

if TYPE_CHECKING:
    from . import MachineMember

CODE = "LIS502"
NAME = "duplicate-axis-name"
SEVERITY = "warning"
FIX = "none"
PARAMETERS = ("kopf.log_achs_name",)  # parameters this rule reads
SUMMARY = "Two axis lists of a machine with the same axis name"


def check_machine(members: list[MachineMember], startups: list[Startup]) -> Iterator[Diagnostic]:
    for member, other in first_uses(members, "name"):
        line, column = other[1].get("name_at") or (1, 1)
        yield diagnostic(
            CODE,
            member,
            "name_at",
            f"axis name kopf.log_achs_name `{member[1]['name']}`{unset_note(member, 'name_at')} is also used by {other[0]}; give each "
            "axis its own name",
            Severity.WARNING,
            [Related(other[0], line, column, "kopf.log_achs_name", "first use")],
        )

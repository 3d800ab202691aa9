"""
What
----
A gantry slave (`kenngr.gantry_ax_nr` set) whose master — the axis with that
logical axis number — is not among the machine's axis lists.

Why
---
The slave follows its master; with a wrong number it is coupled to the wrong
axis or to none, and the gantry difference monitoring compares the wrong pair.

Example
-------
```
# file: achsmds1.lis
kopf.achs_nr          1
kopf.log_achs_name    X1
```

```
# file: achsmds2.lis
kopf.achs_nr          2
kopf.log_achs_name    X2
kenngr.gantry_ax_nr   7          ( no list of this machine has kopf.achs_nr 7
```

Use instead
-----------
With achsmds1.lis as it is, name the master's logical axis number:

```
# file: achsmds2.lis
kopf.achs_nr          2
kopf.log_achs_name    X2
kenngr.gantry_ax_nr   1          ( the master's kopf.achs_nr
```

Reference
---------
P-AXIS-00070 (axis number of the gantry master), TF5200 gantry manual.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from ..core.diagnostics import Diagnostic, Severity
from ..machine.startup import diagnostic

if TYPE_CHECKING:
    from ..machine.resolved import Machine

CODE = "LIS503"
NAME = "gantry-master-missing"
FIX = "none"
PARAMETERS = ("kenngr.gantry_ax_nr", "kopf.achs_nr")  # parameters this rule reads
SUMMARY = "Gantry slave whose master axis is not in the machine"


def check_machine(machine: Machine) -> Iterator[Diagnostic]:
    members = machine.numbered()  # not by a template number TwinCAT repeats in every export
    # A master number that lists carry, even as a template number repeated in several tree items, is not
    # missing: which of those axes leads cannot be told, but the message would say no list has it.
    numbers = {info.get("achs_nr") for _, info in machine.members}
    for member in members:
        master = member[1]["gantry_ax_nr"]
        if master and master not in numbers:
            yield diagnostic(
                CODE,
                member,
                "gantry_at",
                f"kenngr.gantry_ax_nr {master} names a gantry master, but no axis list of this machine "
                "has that kopf.achs_nr",
                Severity.WARNING,
            )

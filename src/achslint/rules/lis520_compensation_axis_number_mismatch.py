"""
What
----
An axis compensation list whose logical axis number `kopf.achs_nr`
(P-COMP-00001) is not the axis the start-up list assigns it to with
`achs_kw_log_ax_nr[i]` (P-STUP-00036). A `kopf.achs_nr` the list does not
write is 0, which is no axis number. Only the compensation lists the CNC reads
are judged (below `zahl_kw` when it is written, LIS516).

Why
---
When an axis loads the compensation list assigned to it, the CNC compares
the list's `kopf.achs_nr` with the number of that axis. If they differ it
stops interpreting the list (CNC error 110229): the axis runs without the
compensation. A list copied from another axis with its header unchanged, or
the assignment edited and the list not, is the usual cause.

Example
-------
```
# file: hochlauf.lis
zahl_mds                 2
achs_mds[0]              ./achsmds1.lis
achs_mds[1]              ./achsmds2.lis
zahl_kw                  1
achs_kw[0]               ./achskw2.lis
achs_kw_log_ax_nr[0]     2
```

```
# file: achsmds1.lis
kopf.achs_nr          1
kopf.log_achs_name    X
```

```
# file: achsmds2.lis
kopf.achs_nr          2
kopf.log_achs_name    Y
```

```
# file: achskw2.lis
kopf.achs_nr                 1          ( copied from the list of X
kopf.log_achs_name           Y
kw.ssfk.unit                 1
kw.ssfk.interval        200000
kw.ssfk.kw_nr_max            2
kw.ssfk.table[0].pos         0
kw.ssfk.table[1].pos         8
```

Use instead
-----------
```
# file: achskw2.lis
kopf.achs_nr                 2
kopf.log_achs_name           Y
kw.ssfk.unit                 1
kw.ssfk.interval        200000
kw.ssfk.kw_nr_max            2
kw.ssfk.table[0].pos         0
kw.ssfk.table[1].pos         8
```

Reference
---------
P-COMP-00001 (kopf.achs_nr of a compensation list: the axis it belongs to,
0 not allowed), P-STUP-00036 (achs_kw_log_ax_nr[i]); TF5200 diagnosis manual,
error 110229 (logical axis number in the compensation value list and in the
start-up list not equal: interpretation of the list aborted).
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from ..catalogue.kinds import COMPENSATION
from ..core.diagnostics import Diagnostic, Severity
from ..core.files import shown_path
from ._crosslist import by_number, every_axis_list_read
from ._kindvalues import (
    at_setting,
    compensation_assignments,
    loaded_settings,
    related_at,
    unusable,
    whole,
    written,
)

if TYPE_CHECKING:
    from ..machine.resolved import Machine

CODE = "LIS520"
NAME = "compensation-axis-number-mismatch"
FIX = "none"
SUMMARY = "Compensation list's kopf.achs_nr differs from its achs_kw_log_ax_nr (the CNC drops the list)"


def check_machine(machine: Machine) -> Iterator[Diagnostic]:
    startup = machine.startup
    read = startup is not None and every_axis_list_read(startup, machine.members)
    numbers = by_number(machine.members) if read else None
    for found in compensation_assignments(machine):
        entry, assignment = found.entry, found.setting
        expected = whole(assignment)
        if entry.path is None or assignment is None or not expected:
            continue  # missing, or no assignment (or 0, no axis): LIS519
        if numbers is not None and expected not in numbers:
            continue  # assigned to an axis the machine does not have: no axis loads it (LIS519)
        settings = loaded_settings(machine, entry, "axis compensation list", COMPENSATION)
        if settings is None:
            continue
        header = written(settings).get("kopf.achs_nr")
        if "kopf.achs_nr" in unusable(settings):
            continue  # written, but not a usable number: the list's own finding (LIS201, LIS202)
        number = whole(header) if header is not None else 0
        if number == expected or number is None:
            continue
        says = (
            f"the axis compensation list gives logical axis {number}, but the start-up list assigns it to "
            f"axis {expected} (`{assignment.canonical}`): the CNC stops interpreting the list when axis "
            f"{expected} loads it (error 110229), so the axis runs without this compensation; set "
            f"kopf.achs_nr {expected}, or assign the list to the axis it was made for"
        )
        assert startup is not None  # it named the list
        related = [related_at(str(startup.path), assignment, "the assignment")]
        if header is not None:
            yield at_setting(
                CODE,
                shown_path(entry.path),
                header,
                Severity.ERROR,
                f"`kopf.achs_nr` = {number}: {says}",
                related,
            )
        else:
            yield Diagnostic(
                shown_path(entry.path),
                1,
                1,
                1,
                2,
                CODE,
                Severity.ERROR,
                f"`kopf.achs_nr` is not written, so it is 0: {says}",
                related=tuple(related),
            )

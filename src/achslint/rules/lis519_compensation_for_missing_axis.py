"""
What
----
An axis compensation list `achs_kw[i]` (P-STUP-00017) of the start-up list
that is assigned to no axis of the machine: its axis assignment
`achs_kw_log_ax_nr[i]` (P-STUP-00036) is not written or 0, or names a logical axis
number that none of the machine's axis lists has as its `kopf.achs_nr`
(P-AXIS-00016). Only the compensation lists the CNC reads are judged (below
`zahl_kw` when it is written, LIS516), and a missing axis only when every
axis list of the start-up list could be read.

Why
---
The start-up list assigns each compensation list to the axis that uses it by
logical axis number; a list is interpreted when that axis loads it. A
compensation list without an assignment, or with the number of an axis the
machine does not have, is used by no axis: the compensation it holds never
takes effect, and the axis it was meant for runs without it. A number not
changed after an axis was renumbered, or an entry copied without its
assignment, is the usual cause. TwinCAT writes these entries itself; the
finding is for start-up lists kept by hand.

Example
-------
```
# file: hochlauf.lis
zahl_mds                 1
achs_mds[0]              ./achsmds1.lis
zahl_kw                  1
achs_kw[0]               ./achskw1.lis
achs_kw_log_ax_nr[0]     2                 ( the machine has no axis 2
```

```
# file: achsmds1.lis
kopf.achs_nr          1
kopf.log_achs_name    X
```

```
# file: achskw1.lis
kopf.achs_nr                 2
kopf.log_achs_name           X
kw.ssfk.unit                 1
kw.ssfk.interval        200000
kw.ssfk.kw_nr_max            2
kw.ssfk.table[0].pos         0
kw.ssfk.table[1].pos        12
```

Use instead
-----------
The list assigned to the axis it was measured on, with that axis's number:

```
# file: hochlauf.lis
zahl_mds                 1
achs_mds[0]              ./achsmds1.lis
zahl_kw                  1
achs_kw[0]               ./achskw1.lis
achs_kw_log_ax_nr[0]     1
```

```
# file: achskw1.lis
kopf.achs_nr                 1
kopf.log_achs_name           X
kw.ssfk.unit                 1
kw.ssfk.interval        200000
kw.ssfk.kw_nr_max            2
kw.ssfk.table[0].pos         0
kw.ssfk.table[1].pos        12
```

Reference
---------
P-STUP-00016 / P-STUP-00017 (zahl_kw, achs_kw[i]), P-STUP-00036
(achs_kw_log_ax_nr[i]: the logical axis number each compensation list belongs
to, 1 … MAX(UNS16), default 0), P-AXIS-00016 (kopf.achs_nr). The manuals name
no CNC error for a compensation list assigned to an axis that does not exist.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from ..core.diagnostics import Diagnostic, Related, Severity
from ..machine.startup import at_entry
from ._crosslist import by_number, every_axis_list_read
from ._kindvalues import at_setting, compensation_assignments, whole

if TYPE_CHECKING:
    from ..machine.resolved import Machine

CODE = "LIS519"
NAME = "compensation-for-missing-axis"
FIX = "none"
SUMMARY = "Axis compensation list assigned to no axis of the machine (achs_kw_log_ax_nr)"


def check_machine(machine: Machine) -> Iterator[Diagnostic]:
    assignments = compensation_assignments(machine)
    startup = machine.startup
    if startup is None or not assignments:
        return
    numbers = by_number(machine.members) if every_axis_list_read(startup, machine.members) else None
    name = str(startup.path)
    for found in assignments:
        entry, key, assignment = found.entry, found.key, found.setting
        if found.unusable:
            continue  # written, but not a usable number: the start-up list's own finding (LIS202)
        if assignment is None:
            yield at_entry(
                CODE,
                startup.path,
                entry,
                Severity.WARNING,
                f"`{entry.key}` names the axis compensation list `{entry.raw}`, but the start-up list does not "
                f"assign it to an axis: `{key}` is not written, so no axis uses the list; add `{key}` with "
                "the logical axis number of the axis it compensates",
            )
            continue
        number = whole(assignment)
        if number == 0:  # the default, accepted as written: it is no logical axis number (1 ... MAX(UNS16))
            yield at_setting(
                CODE,
                name,
                assignment,
                Severity.WARNING,
                f"`{key}` = 0 assigns the axis compensation list `{entry.raw}` to no axis (logical axis numbers "
                "start at 1), so no axis uses the list; give the number of the axis it compensates",
                [Related(name, entry.line, entry.column, entry.key, "the compensation list")],
            )
            continue
        if numbers is None or number is None or number in numbers:
            continue
        known = ", ".join(str(n) for n in sorted(numbers)) or "none"
        yield at_setting(
            CODE,
            name,
            assignment,
            Severity.WARNING,
            f"`{key}` = {number} assigns the axis compensation list `{entry.raw}` to logical axis {number}, "
            f"but no axis list of the machine has kopf.achs_nr {number} (the machine's axes: {known}): no "
            "axis uses the list; give the number of the axis it compensates",
            [Related(name, entry.line, entry.column, entry.key, "the compensation list")],
        )

"""
What
----
A count in the start-up list that is larger than its entries: `zahl_mds`
(P-STUP-00014) counts an axis list `achs_mds[i]` (P-STUP-00015) that the
start-up list does not name, or `zahl_kw` (P-STUP-00016) an axis
compensation list `achs_kw[i]` (P-STUP-00017) that it does not name. Every
index from 0 up to the count minus one needs an entry. A count above the
largest the CNC accepts (32) is LIS202's finding alone: how the CNC reads such
a count is not documented, so no entry is called missing for it.

Why
---
The CNC opens as many lists as the count says, `achs_mds[0]` up to
`achs_mds[zahl_mds - 1]`. For an index without an entry it tries to open a
file that is not there, and the start-up is aborted. A list removed from the
start-up list without lowering the count is the usual cause, or a gap in the
indices.

Example
-------
```
# file: hochlauf.lis
zahl_mds          3                  ( achs_mds[2] is not named
achs_mds[0]       ./achsmds1.lis
achs_mds[1]       ./achsmds2.lis
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

Use instead
-----------
The count of the entries the start-up list has:

```
# file: hochlauf.lis
zahl_mds          2
achs_mds[0]       ./achsmds1.lis
achs_mds[1]       ./achsmds2.lis
```

Reference
---------
P-STUP-00014 (zahl_mds: the number of axis lists read), P-STUP-00015
(achs_mds[i]: the CNC tries to open lists it does not know, reports an error
and aborts the start-up), P-STUP-00016 (zahl_kw), P-STUP-00017 (achs_kw[i]);
list format facts §9 (missing lists abort the start-up).
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from ..core.diagnostics import Diagnostic, Severity
from ._crosslist import COUNTED, MAX_ENTRIES, index

if TYPE_CHECKING:
    from ..machine.resolved import Machine

CODE = "LIS517"
NAME = "count-without-entry"
FIX = "none"
SUMMARY = "zahl_mds or zahl_kw counts an entry the start-up list does not name"

SHOWN = 6  # more missing entries are shortened in messages


def _span(key: str, count: int) -> str:
    return f"{key}[0]" if count == 1 else f"{key}[0] … {key}[{count - 1}]"


def check_machine(machine: Machine) -> Iterator[Diagnostic]:
    startups = machine.startups
    for startup in startups:
        for count_key, (entry_key, _, _) in COUNTED.items():
            count = startup.counts.get(count_key)
            if count is None or count.value is None or not 0 < count.value <= MAX_ENTRIES:
                continue  # out of range: LIS202 on the count's own line says so
            entries = startup.axes if entry_key == "achs_mds" else startup.compensations
            named = {index(entry) for entry in entries}
            missing = [number for number in range(count.value) if number not in named]
            if not missing:
                continue
            shown = ", ".join(f"{entry_key}[{number}]" for number in missing[:SHOWN])
            more = f" and {len(missing) - SHOWN} more" if len(missing) > SHOWN else ""
            given = len([number for number in named if number < count.value])
            end = count.column + len(count.raw)
            yield Diagnostic(
                str(startup.path),
                count.line,
                count.column,
                count.line,
                end,
                CODE,
                Severity.ERROR,
                f"`{count_key} {count.raw}` counts {_span(entry_key, count.value)}, but the "
                f"start-up list does not name {shown}{more}: the CNC tries to open a list that is not named "
                f"and aborts the start-up; name a list for each missing index, or number the entries from 0 "
                f"without a gap and set {count_key} to how many there are ({given})",
            )

"""
What
----
A start-up list entry that its count leaves out: an axis list
`achs_mds[i]` (P-STUP-00015) whose index is not below `zahl_mds`
(P-STUP-00014), or an axis compensation list `achs_kw[i]` (P-STUP-00017)
whose index is not below `zahl_kw` (P-STUP-00016). A start-up list that
writes no count is left alone: TwinCAT writes both counts itself, and
achslint does not guess what a hand-kept list without one means.

Why
---
The count says how many entries the CNC reads: `achs_mds[0]` up to
`achs_mds[zahl_mds - 1]`. Entries beyond it are not considered, so the list
such an entry names is never loaded: its axis does not exist in the CNC, or
its compensation is not applied. A list added to the start-up list without
raising the count is the usual cause.

Example
-------
```
# file: hochlauf.lis
zahl_mds          1
achs_mds[0]       ./achsmds1.lis
achs_mds[1]       ./achsmds2.lis      ( beyond zahl_mds 1: never loaded
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
A count that covers every entry:

```
# file: hochlauf.lis
zahl_mds          2
achs_mds[0]       ./achsmds1.lis
achs_mds[1]       ./achsmds2.lis
```

Reference
---------
P-STUP-00014 (zahl_mds: the number of axis lists read),
P-STUP-00015 (achs_mds[i]: files beyond zahl_mds are not considered),
P-STUP-00016 (zahl_kw), P-STUP-00017 (achs_kw[i], the same for compensation
lists); list format facts §9 (excess entries are ignored).
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from ..core.diagnostics import Diagnostic, Related, Severity
from ..machine.startup import at_entry
from ._crosslist import COUNTED, MAX_ENTRIES, index

if TYPE_CHECKING:
    from ..machine.resolved import Machine
    from ..machine.startup import Startup, StartupEntry

CODE = "LIS516"
NAME = "entry-beyond-count"
FIX = "none"
SUMMARY = "Start-up list entry beyond zahl_mds or zahl_kw: the list it names is never loaded"

_WHAT = {"achs_mds": "axis list", "achs_kw": "axis compensation list"}


def _span(key: str, count: int) -> str:
    """The entries a count lets the CNC read, in words."""
    if count <= 0:
        return f"no {key} entry"
    return f"{key}[0] only" if count == 1 else f"{key}[0] … {key}[{count - 1}] only"


def _at(startup: Startup, entry: StartupEntry, message: str, related: tuple[Related, ...] = ()) -> Diagnostic:
    return at_entry(CODE, startup.path, entry, Severity.WARNING, message, related)


def check_machine(machine: Machine) -> Iterator[Diagnostic]:
    startups = machine.startups
    for startup in startups:
        for count_key, (entry_key, _, _) in COUNTED.items():
            entries = startup.axes if entry_key == "achs_mds" else startup.compensations
            if not entries:
                continue
            what = _WHAT[entry_key]
            count = startup.counts.get(count_key)
            if count is None:
                continue  # no count written (TwinCAT writes both): nothing to compare the entries with
            if count.value is None:
                continue  # not a number: the start-up list's own finding
            for entry in entries:
                if index(entry) < count.value:
                    continue
                # Raising the count is the remedy only up to its largest value (32): an entry at index 32 or
                # above is never loaded whatever the count says (LIS202 refuses a larger count).
                remedy = (
                    f"raise {count_key} to {index(entry) + 1} at least, or remove the entry"
                    if index(entry) < MAX_ENTRIES
                    else f"no {count_key} reaches it ({count_key} is at most {MAX_ENTRIES}, so {entry_key}"
                    f"[{MAX_ENTRIES - 1}] is the last entry read): give the list a free index below "
                    f"{MAX_ENTRIES}, or remove the entry"
                )
                yield _at(
                    startup,
                    entry,
                    f"`{entry.key}` lies beyond `{count_key} {count.raw}`: the CNC reads {_span(entry_key, count.value)}"
                    f", so the {what} `{entry.raw}` is never loaded; {remedy}",
                    (Related(str(startup.path), count.line, count.column, count_key, "the count"),),
                )

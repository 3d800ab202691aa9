"""
What
----
One axis list file named twice in a start-up list: by two `achs_mds[i]`
entries (P-STUP-00015) that the CNC reads (below `zahl_mds`, when it is
written), or by an
`achs_mds[i]` entry and the default axis list entry `default_achs_mds`
(P-STUP-00035). Entries are compared by the file they lead to, so
`./achsmds1.lis` and `../listen/achsmds1.lis` (or a link to it) are the same
list.

Why
---
Each `achs_mds[i]` entry is an axis of its own. The same file twice gives
two axes with one logical axis number (`kopf.achs_nr`, P-AXIS-00016), and
the CNC rejects the data of the second (CNC error 110064): one axis of the
machine has no list, usually the one whose entry was copied and not
changed. A default axis list needs `kopf.achs_nr` 0 (P-ERR-110300: the
start-up is aborted otherwise) while an axis needs a number above 0
(P-ERR-110076), so one file cannot be both. (Two entries for one file do not
show as LIS501: it is one list.)

Example
-------
```
# file: hochlauf.lis
zahl_mds          2
achs_mds[0]       ./achsmds1.lis
achs_mds[1]       ./achsmds1.lis      ( copied, meant ./achsmds2.lis
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
Each entry names the list of its own axis:

```
# file: hochlauf.lis
zahl_mds          2
achs_mds[0]       ./achsmds1.lis
achs_mds[1]       ./achsmds2.lis
```

Reference
---------
P-STUP-00015 (achs_mds[i]), P-STUP-00014 (zahl_mds), P-STUP-00035
(default_achs_mds), P-AXIS-00016 (a logical axis number is used once);
P-ERR-110300, P-ERR-110076; TF5200 diagnosis manual, error 110064 (a logical
axis number given to two axes: the second axis's data is rejected).
"""

from __future__ import annotations

import os
from collections.abc import Iterator
from pathlib import Path
from typing import TYPE_CHECKING

from ..core.diagnostics import Diagnostic, Related, Severity
from ..core.files import same_file
from ..machine.startup import at_entry

if TYPE_CHECKING:
    from ..machine.resolved import Machine
    from ..machine.startup import StartupEntry

CODE = "LIS518"
NAME = "list-named-twice"
FIX = "none"
SUMMARY = "Start-up list names one axis list file twice (two axes, or an axis and the default list)"


def check_machine(machine: Machine) -> Iterator[Diagnostic]:
    startups = machine.startups
    for startup in startups:
        first: dict[object, StartupEntry] = {}
        entries = [startup.default] if startup.default is not None else []
        for entry in sorted([*entries, *startup.loaded_axes()], key=lambda entry: entry.line):
            if entry.path is None or same_file(entry.path, startup.path):
                continue  # missing, not read, or the start-up list itself: LIS504
            earlier = first.setdefault(_file_key(entry.path), entry)
            if earlier is entry or earlier.key == entry.key:
                continue  # one entry written twice is the start-up list's own matter
            if "default_achs_mds" in (earlier.key, entry.key):
                consequence = (
                    "which is also the default axis list: a default list must have kopf.achs_nr 0 (the CNC "
                    "aborts the start-up otherwise) and an axis a number above 0, so one file cannot be "
                    "both; give the axis a list of its own"
                )
            else:
                consequence = (
                    "which is already an axis of this machine: the second axis has the same kopf.achs_nr, and "
                    "the CNC rejects its data (error 110064); name the list of the axis meant, or remove "
                    "the entry and lower zahl_mds"
                )
            shown = f"`{entry.raw}`" if entry.raw == earlier.raw else f"`{entry.raw}` (`{earlier.raw}`)"
            yield at_entry(
                CODE,
                startup.path,
                entry,
                Severity.ERROR,
                f"`{entry.key}` names {shown}, the file `{earlier.key}` names, {consequence}",
                (Related(str(startup.path), earlier.line, earlier.column, earlier.key, "named first"),),
            )


def _file_key(path: Path) -> object:
    """One file, however it is named: device and inode (hard links and symbolic links alike), else its real
    path when it cannot be looked at."""
    try:
        info = os.stat(path)
    except OSError:
        return os.path.realpath(path)
    return (info.st_dev, info.st_ino)

"""
What
----
A channel list (`sda_mds[i]` of the start-up list, read with `default_sda_mds`
underneath) that gives one logical axis a second, different name: two slots
of the axis group (`gruppe[g].achse[i].log_achs_nr`, P-CHAN-00035) with the
same number, or two spindles (`spindel[i].log_achs_nr`, P-CHAN-00036).

Why
---
Each slot of a channel list names one axis: its `bezeichnung` (P-CHAN-00006,
P-CHAN-00007) is the name NC programs write, its `log_achs_nr` the
`kopf.achs_nr` of the axis list. A second slot with the same number does not
add an axis; it makes one axis answer to two names, so a program can command
it twice in one block, and the slot meant for another axis is missing that
axis. `explain` and `dry-run` use the first name and say so. A spindle that
also stands in the axis group with its number is LIS513's finding, not this
one's: a spindle cannot be a path axis.

Example
-------
```
# file: hochlauf.lis
zahl_mds          2
achs_mds[0]       ./achsmds1.lis
achs_mds[1]       ./achsmds2.lis
sda_mds[0]        ./sda_mds1.lis
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
# file: sda_mds1.lis
gruppe[0].achse[0].bezeichnung   X
gruppe[0].achse[0].log_achs_nr   1
gruppe[0].achse[1].bezeichnung   Y
gruppe[0].achse[1].log_achs_nr   1          ( meant 2
```

Use instead
-----------
Each slot with the number of its own axis:

```
# file: sda_mds1.lis
gruppe[0].achse[0].bezeichnung   X
gruppe[0].achse[0].log_achs_nr   1
gruppe[0].achse[1].bezeichnung   Y
gruppe[0].achse[1].log_achs_nr   2
```

Reference
---------
P-CHAN-00006 / P-CHAN-00035 (name and logical number of an axis of the
channel's axis group), P-CHAN-00007 / P-CHAN-00036 (of a spindle), P-STUP-00009
(sda_mds[i]), P-AXIS-00016 (kopf.achs_nr). No CNC error id is documented for a
logical axis with two names.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from ..core.diagnostics import Diagnostic, Related, Severity

if TYPE_CHECKING:
    from ..machine.resolved import Machine

CODE = "LIS508"
NAME = "axis-named-twice-in-channel"
FIX = "none"
SUMMARY = "Channel list gives one logical axis two different names"


def check_machine(machine: Machine) -> Iterator[Diagnostic]:
    for _, channel in machine.channel_lists():  # a missing or unreadable one is LIS504
        for first, again in channel.other_names():
            end = again.at.end_column or again.at.column + len(again.name)
            yield Diagnostic(
                again.at.path,
                again.at.line,
                again.at.column,
                again.at.line,
                end,
                CODE,
                Severity.WARNING,
                f"{again.slot} names logical axis {again.logical_number} `{again.name}`, but {first.slot} "
                f"already names it `{first.name}`: an axis has one name in a channel; give this slot the "
                "logical number of the axis it is meant for, or remove it",
                related=(
                    Related(
                        first.at.path,
                        first.at.line,
                        first.at.column,
                        f"{first.slot}.bezeichnung",
                        "first name",
                    ),
                ),
            )

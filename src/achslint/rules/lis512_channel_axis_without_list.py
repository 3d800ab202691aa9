"""
What
----
A channel list (`sda_mds[i]` of the start-up list, with `default_sda_mds`
underneath) that maps an axis of its axis group
(`gruppe[g].achse[i].log_achs_nr`, P-CHAN-00035) or a spindle
(`spindel[i].log_achs_nr`, P-CHAN-00036) to a logical axis number that no
axis list of the start-up list has as its `kopf.achs_nr` (P-AXIS-00016).

The check runs only when every axis list the start-up list names could be
read: a missing or unreadable one is LIS504's finding (or its own), and its
number is not known.

Why
---
The logical axis number is how the channel finds an axis's data: the CNC
looks for the axis list with that `kopf.achs_nr`. At start-up, an axis-group
number that no axis list has leaves the whole channel without axes (CNC
error 3210), so no program of that channel can move. A spindle whose number
has no axis list has no axis data to run with. `explain` and the machine
dry-run leave the slot's name out, so a homing program that names it gets
LIS602.

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
gruppe[0].achse[1].log_achs_nr   7          ( no axis list has kopf.achs_nr 7
```

Use instead
-----------
The number of the axis list that holds the axis's data (or add that axis list
to the start-up list):

```
# file: sda_mds1.lis
gruppe[0].achse[0].bezeichnung   X
gruppe[0].achse[0].log_achs_nr   1
gruppe[0].achse[1].bezeichnung   Y
gruppe[0].achse[1].log_achs_nr   2
```

Reference
---------
P-CHAN-00035 (logical number of an axis of the channel), P-CHAN-00036 (of a
spindle), P-AXIS-00016 (kopf.achs_nr), P-STUP-00009 (sda_mds[i]),
P-STUP-00015 (achs_mds[i]); TF5200 diagnosis manual, error 3210 (at start-up
the channel whose list names an unknown logical axis number gets no axes).
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from ..core.diagnostics import Diagnostic, Severity
from ._crosslist import at_channel_axis, axis_words, by_number, every_axis_list_read

if TYPE_CHECKING:
    from ..machine.resolved import Machine

CODE = "LIS512"
NAME = "channel-axis-without-list"
FIX = "none"
SUMMARY = "Channel list maps an axis or spindle to a logical axis number no axis list has"

SHOWN_NUMBERS = 12  # a longer list of the machine's numbers is shortened in messages


def _numbers(known: list[int]) -> str:
    if not known:
        return "the start-up list names no axis list"
    shown = ", ".join(str(number) for number in known[:SHOWN_NUMBERS])
    more = f" and {len(known) - SHOWN_NUMBERS} more" if len(known) > SHOWN_NUMBERS else ""
    return f"its axis lists have {shown}{more}"


def check_machine(machine: Machine) -> Iterator[Diagnostic]:
    members = machine.members
    numbers = by_number(members)
    known = sorted(numbers)
    startup = machine.startup
    if startup is None or not every_axis_list_read(startup, members):
        return  # a list not read: its logical axis number is not known
    for _, channel in machine.channel_lists():
        for axis in channel.axes:
            if axis.logical_number in numbers:
                continue
            if axis.spindle:
                consequence = "the CNC has no axis data for this spindle"
            else:
                consequence = "at start-up the CNC leaves this channel without any axes (error 3210)"
            yield at_channel_axis(
                CODE,
                axis,
                Severity.ERROR,
                f"{axis_words(axis)}: no axis list of {startup.path.name} has kopf.achs_nr "
                f"{axis.logical_number} ({_numbers(known)}), so {consequence}; write the logical axis number "
                "of the axis list meant, or name that axis list in the start-up list (achs_mds[i])",
            )

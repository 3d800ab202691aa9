"""
What
----
A channel list that names a gantry slave as an axis of the channel: a slot of
its axis group (`gruppe[g].achse[i].log_achs_nr`, P-CHAN-00035) or a spindle
(`spindel[i].log_achs_nr`, P-CHAN-00036) whose axis list couples the axis to a
master with `kenngr.gantry_ax_nr` (P-AXIS-00070).

Why
---
`kenngr.gantry_ax_nr` makes a static gantry: the CNC couples the slave to its
master at start-up, in the position controller. The slave is no axis of any
channel; it moves when the program moves its master, and homes with it. The
TF5200 gantry manual says a gantry slave may not be assigned to an NC channel,
and the CNC refuses a gantry slave it is handed as a channel axis (CNC error
21020). Only the master belongs in the channel list.

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
kopf.log_achs_name    Y
kenngr.achs_mode      0x10001    ( LINEAR | GANTRY_MASTER
```

```
# file: achsmds2.lis
kopf.achs_nr          2
kopf.log_achs_name    Y2
kenngr.achs_mode      0x20001    ( LINEAR | GANTRY_SLAVE
kenngr.gantry_ax_nr   1
```

```
# file: sda_mds1.lis
gruppe[0].achse[0].bezeichnung   Y
gruppe[0].achse[0].log_achs_nr   1
gruppe[0].achse[1].bezeichnung   Y2
gruppe[0].achse[1].log_achs_nr   2          ( the slave follows Y by itself
```

Use instead
-----------
Only the master in the channel:

```
# file: sda_mds1.lis
gruppe[0].achse[0].bezeichnung   Y
gruppe[0].achse[0].log_achs_nr   1
```

Reference
---------
P-AXIS-00070 (kenngr.gantry_ax_nr: the slave is not known in the channel and
moves when its master is programmed), P-CHAN-00035, P-CHAN-00036; TF5200
gantry manual (configuration of the slave axis: not assigned to any NC
channel); TF5200 diagnosis manual, error 21020 (a gantry slave handed to the
channel as an axis is refused).
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from ..core.diagnostics import Diagnostic, Severity
from ._crosslist import at_channel_axis, at_member, axis_words, by_number
from .lis507_gantry_master_chain import coupling_faults

if TYPE_CHECKING:
    from ..machine.resolved import Machine

CODE = "LIS514"
NAME = "gantry-slave-in-channel"
FIX = "none"
PARAMETERS = ("kenngr.gantry_ax_nr", "kopf.achs_nr")  # parameters this rule reads
SUMMARY = "Channel list names a gantry slave, which moves only with its master"


def check_machine(machine: Machine) -> Iterator[Diagnostic]:
    members = machine.members
    numbers = by_number(members)
    # A slave in a circle or a chain of couplings is LIS507's: whichever of them the CNC takes for the master,
    # telling the user to program "its master" would contradict that finding.
    master_of = {
        number: master
        for number, (_, summary) in numbers.items()
        if isinstance(master := summary.get("gantry_ax_nr"), int) and master > 0
    }
    tangled = set(coupling_faults(master_of))
    for _, channel in machine.channel_lists():
        names = {axis.logical_number: axis.name for axis in reversed(channel.axes) if not axis.spindle}
        for axis in channel.axes:
            member = numbers.get(axis.logical_number)
            master = member[1].get("gantry_ax_nr") if member is not None else None
            if member is None or not isinstance(master, int) or master <= 0 or axis.logical_number in tangled:
                continue  # no list (LIS512), no slave, or a coupling LIS507 reports (itself, chain, circle)
            program = f"`{names[master]}`" if master in names else f"axis {master}"
            yield at_channel_axis(
                CODE,
                axis,
                Severity.ERROR,
                f"{axis_words(axis)} is a gantry slave: its axis list {member[0]} couples it to axis {master} "
                f"(kenngr.gantry_ax_nr {master}), and a gantry slave is no channel axis: it moves with its "
                "master, and the CNC refuses it as an axis of the channel (error 21020); remove this slot "
                f"and program its master {program}, or remove kenngr.gantry_ax_nr if the axis should move on "
                "its own",
                [at_member(member, "gantry_at", "kenngr.gantry_ax_nr", "the gantry coupling")],
            )

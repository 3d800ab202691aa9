"""
What
----
A channel list whose slot and axis list disagree on whether the axis is a
spindle: a spindle of the channel (`spindel[i].log_achs_nr`, P-CHAN-00036)
whose axis list is not a spindle, or an axis of the channel's axis group
(`gruppe[g].achse[i].log_achs_nr`, P-CHAN-00035) whose axis list is one. An
axis list is a spindle when its `kenngr.achs_typ` (P-AXIS-00018) is 4
(`ACHSTYP_SPINDEL`); unset, it is a linear axis.

Why
---
The CNC sets a spindle up in its spindle interpolator and a path axis in the
channel's axis group, after the axis list's type. A spindle slot that leads to
a linear or rotary axis makes the CNC start without any axes in that channel
(CNC error 110304). A spindle in the axis group cannot be a path axis at all:
the CNC aborts the start-up (CNC error 21238). A spindle that should also
move as a rotary (C) axis is switched over by the NC program, not by a second
slot in the axis group.

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
kopf.log_achs_name    S
kenngr.achs_typ       1          ( meant as the spindle, but typed linear
```

```
# file: sda_mds1.lis
gruppe[0].achse[0].bezeichnung   X
gruppe[0].achse[0].log_achs_nr   1
spindel[0].bezeichnung           S
spindel[0].log_achs_nr           2
```

Use instead
-----------
The spindle's axis list typed as a spindle (modulo, as a spindle must be, and
homing without reversal):

```
# file: achsmds2.lis
kopf.achs_nr          2
kopf.log_achs_name    S
kenngr.achs_typ       4
kenngr.achs_mode      0x4
kenngr.ref_ohne_rev   1
```

Reference
---------
P-AXIS-00018 (kenngr.achs_typ: 1 linear, 2 rotary, 4 spindle), P-CHAN-00035
(an axis group's logical axis numbers: a spindle may not be a path axis),
P-CHAN-00036 (a spindle's logical axis number), P-AXIS-00016; TF5200 diagnosis
manual, errors 110304 (spindle requested, axis is no spindle: the channel gets
no axes) and 21238 (a path axis that is a spindle: start-up aborted).
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from ..core.diagnostics import Diagnostic, Severity
from ._crosslist import at_channel_axis, at_member, axis_words, by_number

if TYPE_CHECKING:
    from ..machine.resolved import Machine
    from ..machine.startup import Member

CODE = "LIS513"
NAME = "channel-axis-type-mismatch"
FIX = "none"
PARAMETERS = ("kenngr.achs_typ", "kopf.achs_nr")  # parameters this rule reads
SUMMARY = "Channel spindle whose axis list is no spindle, or axis-group axis whose list is a spindle"

_TYPES = {"T": "a linear axis", "R": "a rotary axis", "S": "a spindle"}


def _written(member: Member) -> str:
    """The axis list's type as it is written: `kenngr.achs_typ 2 makes it a rotary axis`, or the default."""
    info = member[1]
    written = info.get("axis_type_written")
    if written is None:
        return "kenngr.achs_typ is not set, so it is a linear axis"
    where = "" if info.get("axis_type_at") else " in the default axis list"
    return f"kenngr.achs_typ {written}{where} makes it {_TYPES[info.get('axis_type', 'T')]}"


def check_machine(machine: Machine) -> Iterator[Diagnostic]:
    members = machine.members
    numbers = by_number(members)
    for _, channel in machine.channel_lists():
        # a number the channel gives to a path axis and to a spindle is LIS701's: one of the two slots is
        # wrong, and changing the axis list's type (this rule's advice) would only move the fault
        both = {a.logical_number for a in channel.axes if a.spindle} & {
            a.logical_number for a in channel.axes if not a.spindle
        }
        for axis in channel.axes:
            member = numbers.get(axis.logical_number)
            if member is None or axis.logical_number in both:
                continue  # LIS512, LIS701
            is_spindle = member[1].get("axis_type") == "S"
            if axis.spindle == is_spindle:
                continue
            if axis.spindle:
                says = (
                    f"{axis_words(axis)} is a spindle of the channel, but its axis list {member[0]} is no "
                    f"spindle ({_written(member)}): the CNC starts with no axes in this channel (error "
                    "110304); set kenngr.achs_typ 4 in the axis list, or give the spindle the number of its "
                    "own axis list"
                )
            else:
                says = (
                    f"{axis_words(axis)} is an axis of the channel's axis group, but its axis list "
                    f"{member[0]} is a spindle (kenngr.achs_typ {member[1].get('axis_type_written')}): a "
                    "spindle cannot be a path axis and the CNC aborts the start-up (error 21238); name it "
                    "under spindel[i] instead, or give the slot the number of a linear or rotary axis"
                )
            yield at_channel_axis(
                CODE,
                axis,
                Severity.ERROR,
                says,
                [at_member(member, "axis_type_at", "kenngr.achs_typ", "the axis list's type")],
            )

"""
What
----
A channel list that gives one name to two of its path axes
(`gruppe[0].achse[j].bezeichnung`, P-CHAN-00006) or to two of its spindles
(`spindel[i].bezeichnung`, P-CHAN-00007). Names are compared without regard
to case, as NC programs write them. A slot without a logical axis number (0
or none written) is no axis of the channel, so its name is not compared.

Why
---
The name is what an NC program writes to move an axis or to start a spindle,
so it has to say which one is meant: the remark of P-CHAN-00006 requires the
axis names of a channel to be unique. The CNC's check of the channel
parameters at start-up reports two path axes with one name as error 20424
and two spindles with one name as error 20419, and goes on. A slot copied
and given a new logical axis number but not a new name is the usual cause.
(One logical axis with two names is LIS508's finding.)

Example
-------
```
# file: sda_mds1.lis
gruppe[0].achs_anzahl             3
gruppe[0].achse[0].bezeichnung    X
gruppe[0].achse[0].log_achs_nr    1
gruppe[0].achse[1].bezeichnung    Y
gruppe[0].achse[1].log_achs_nr    2
gruppe[0].achse[2].bezeichnung    Y          ( copied from the line above
gruppe[0].achse[2].log_achs_nr    3
```

Use instead
-----------
A name of its own for each axis:

```
# file: sda_mds1.lis
gruppe[0].achs_anzahl             3
gruppe[0].achse[0].bezeichnung    X
gruppe[0].achse[0].log_achs_nr    1
gruppe[0].achse[1].bezeichnung    Y
gruppe[0].achse[1].log_achs_nr    2
gruppe[0].achse[2].bezeichnung    Z
gruppe[0].achse[2].log_achs_nr    3
```

Reference
---------
P-CHAN-00006 (name of a path axis; remark: the names must be unique),
P-CHAN-00007 (name of a spindle); TF5200 diagnosis manual, errors 20424 (two
path axes with the same name) and 20419 (two spindles with the same name),
both response class 1: the start-up is continued.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from ._kindvalues import slots, written

if TYPE_CHECKING:
    from ..core.diagnostics import Diagnostic
    from ._kindvalues import Slot
    from .context import Context

CODE = "LIS702"
NAME = "channel-name-twice"
FIX = "none"
SUMMARY = "Channel list gives one name to two path axes or to two spindles"

_ERROR = {False: ("path axes", 20424), True: ("spindles", 20419)}


def check(ctx: Context) -> Iterator[Diagnostic]:
    first: dict[tuple[bool, str], Slot] = {}
    for slot in slots(written(ctx.settings)):
        if slot.name is None or not str(slot.name.value).strip():
            continue
        if slot.logical_number is None:
            continue  # an empty slot (log_achs_nr 0 or none): no axis, as LIS508, LIS701 and LIS703 count
        earlier = first.setdefault((slot.spindle, str(slot.name.value).upper()), slot)
        if earlier is slot or earlier.name is None:
            continue
        what, error = _ERROR[slot.spindle]
        line = slot.name.line
        start, end = ctx.value_span(line)
        number = slot.logical_number
        if number is not None and number == earlier.logical_number:  # the same axis in two slots
            says = (
                f"{slot.path} repeats {earlier.label}: one axis in two slots is two {what} with one name to "
                f"the CNC (it reports error {error} at start-up); remove one of the slots"
            )
        else:
            says = (
                f"{slot.path} is named `{slot.name.value}`, the name {earlier.label} already has: two {what} "
                f"of a channel cannot share a name (the CNC reports error {error} at start-up) and a program "
                "naming it cannot say which is meant; give this slot a name of its own"
            )
        yield ctx.report(
            CODE,
            line,
            says,
            column=start,
            end_column=end,
            setting=slot.name,
            related=[ctx.related(earlier.name, "first use of the name")],
        )

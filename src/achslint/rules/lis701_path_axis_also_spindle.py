"""
What
----
A channel list that gives one logical axis number to a path axis of its axis
group (`gruppe[0].achse[j].log_achs_nr`, P-CHAN-00035) and to one of its
spindles (`spindel[i].log_achs_nr`, P-CHAN-00036).

Why
---
An axis of the channel is either a path axis, moved by the path interpolator,
or a spindle, run by a spindle interpolator; the remarks of P-CHAN-00035 and
P-CHAN-00036 forbid configuring one logical axis as both. The CNC's check of
the channel parameters at start-up reports it as error 20426 and the start-up
goes on with a channel configuration the manual does not allow. The channel
list alone shows the conflict; when the machine's axis lists are read as well,
LIS513 also says which of the two slots does not match the axis list's type.

Example
-------
```
# file: sda_mds1.lis
gruppe[0].achs_anzahl             2
gruppe[0].achse[0].bezeichnung    X
gruppe[0].achse[0].log_achs_nr    1
gruppe[0].achse[1].bezeichnung    C
gruppe[0].achse[1].log_achs_nr    3
spdl_anzahl                       1
spindel[0].bezeichnung            S
spindel[0].log_achs_nr            3          ( the number of the C axis
```

Use instead
-----------
The spindle with the number of its own axis list:

```
# file: sda_mds1.lis
gruppe[0].achs_anzahl             2
gruppe[0].achse[0].bezeichnung    X
gruppe[0].achse[0].log_achs_nr    1
gruppe[0].achse[1].bezeichnung    C
gruppe[0].achse[1].log_achs_nr    3
spdl_anzahl                       1
spindel[0].bezeichnung            S
spindel[0].log_achs_nr            4
```

Reference
---------
P-CHAN-00035 and P-CHAN-00036 (remarks: a logical axis number may not be a
path axis and a spindle at once; the plausibility check of the channel
parameters reports it at start-up); TF5200 diagnosis manual, error 20426
(an axis configured both as spindle and as path axis; response class 1, the
start-up is continued).
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from ._kindvalues import slots, written

if TYPE_CHECKING:
    from ..core.diagnostics import Diagnostic
    from .context import Context

CODE = "LIS701"
NAME = "path-axis-also-spindle"
FIX = "none"
SUMMARY = "Channel list gives one logical axis number to a path axis and to a spindle"


def check(ctx: Context) -> Iterator[Diagnostic]:
    every = slots(written(ctx.settings))
    # the first path axis with each number (a second one with the same number is LIS508's)
    path_axes = {slot.logical_number: slot for slot in reversed(every) if not slot.spindle}
    for spindle in every:
        number = spindle.logical_number if spindle.spindle else None
        axis = path_axes.get(number) if number is not None else None
        if axis is None or spindle.number is None or axis.number is None:
            continue
        line = spindle.number.line
        start, end = ctx.value_span(line)
        yield ctx.report(
            CODE,
            line,
            f"the spindle {spindle.label} has the logical axis number of the path axis {axis.label}: one axis "
            "cannot be a path axis and a spindle, and the CNC reports error 20426 at start-up; give the "
            "spindle the number of its own axis list, or take the axis out of the axis group",
            column=start,
            end_column=end,
            setting=spindle.number,
            related=[ctx.related(axis.number, "the path axis with this number")],
        )

"""
What
----
A `G74` or move block names an axis the machine does not have under that name:
no axis of the channel list (`gruppe[0].achse[i].bezeichnung`,
`spindel[i].bezeichnung`) — or, without a channel list, no axis list's
`kopf.log_achs_name` — is called so. A gantry slave that the channel list does
not name (its axis list couples it with `kenngr.gantry_ax_nr`) is no axis of
the channel either: the finding says to program its master.

Why
---
The CNC rejects the block and stops the homing program there. A homing program
copied from another machine (`A2 B2` on a machine without rotary axes) or an
axis renamed in the channel list leaves the machine unhomed at power-up.

Example
-------
```
# file: hochlauf.lis
achs_mds[0]           achsmds1.lis
achs_mds[1]           achsmds2.lis
Ende
```
```
# file: achsmds1.lis
kopf.achs_nr          1
kopf.log_achs_name    X
Ende
```
```
# file: achsmds2.lis
kopf.achs_nr          2
kopf.log_achs_name    Y
Ende
```
```
; file: rfp.nc
N10 G74 X1 Y1 A2      (this machine has no A axis)
N20 M30
```

Use instead
-----------
On the same machine, this program:
```
; file: rfp.nc
N10 G74 X1 Y1
N20 M30
```

Reference
---------
P-CHAN-00006 / P-CHAN-00007 (axis and spindle names in the channel),
P-CHAN-00035 / P-CHAN-00036 (their logical axis numbers), P-AXIS-00297,
P-AXIS-00070 (a gantry slave is not known in the channel; it moves when its
master is programmed).
"""

from __future__ import annotations

import difflib
from collections.abc import Iterator
from typing import TYPE_CHECKING

from ..core.diagnostics import Diagnostic, Severity

if TYPE_CHECKING:
    from ..machine.model import ChannelView, Program

CODE = "LIS602"
NAME = "unknown-axis"
FIX = "none"
SUMMARY = "Program names an axis the machine does not have"


def check_program(program: Program, machine: ChannelView) -> Iterator[Diagnostic]:
    from .programcontext import diagnostic, named_words

    names = sorted(machine.axes)
    slaves = {axis.name: axis.gantry_master for axis in machine.followers()}
    for block in program.blocks:
        for word in named_words(block):  # a G74 or move whose values are computed names its axes too
            if word.name in machine.axes:
                continue
            where = f"channel {machine.channel}" if machine.channel_list else "the machine"
            master = slaves.get(word.name)
            if master is not None:
                yield diagnostic(
                    CODE,
                    word.at,
                    f"{where} has no axis named {word.name}: {word.name} is the gantry slave of {master} "
                    "(kenngr.gantry_ax_nr), which belongs to no channel and moves only with its master; "
                    f"program {master} instead (the CNC stops the program at this block)",
                    Severity.ERROR,
                )
                continue
            close = difflib.get_close_matches(word.name, names, n=2, cutoff=0.5)
            hint = f"; did you mean {' or '.join(close)}?" if close else ""
            yield diagnostic(
                CODE,
                word.at,
                f"{where} has no axis named {word.name} (its axes: {', '.join(names) or 'none'}){hint}; "
                "the CNC stops the program at this block",
                Severity.ERROR,
            )

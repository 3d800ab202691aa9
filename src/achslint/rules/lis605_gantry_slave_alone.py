"""
What
----
A `G74` block homes a gantry slave (an axis list with `kenngr.gantry_ax_nr`, or
a slave of a coupled pair in the channel list) while its master is not homed
before it: the master is neither in an earlier G74 block nor earlier (or
together with it) in the same block. In a G74 whose homing order is computed
(`G74 Y2=[P1] Y[P2]`) only a master missing from the block counts; after a
subroutine call, a loop or a jump that achslint does not follow, a master that
part may have homed is not reported (as in LIS606).

Only a slave the program may name counts: on a machine without a channel list
(each axis goes by its `kopf.log_achs_name`), or a slave the channel list names
after all (LIS514) or couples in a pair. A static gantry slave that the channel
list leaves out, as it should, is no axis of the channel: a program naming it
gets LIS602 (program the master), not this finding.

Why
---
The two sides of a gantry are one mechanical unit. With
`kenngr.gantry_slave_no_homing` the slave takes its reference from the master;
without it the slave may be homed, but only once the master is referenced. A
slave homed on its own moves one side of the portal while the other stands,
which skews the beam and trips the gantry difference monitoring.

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
kopf.log_achs_name    Y
Ende
```
```
# file: achsmds2.lis
kopf.achs_nr          2
kopf.log_achs_name    Y2
kenngr.gantry_ax_nr   1
Ende
```
```
; file: rfp.nc
N10 G74 Y2=1          (the slave side alone)
N20 G74 Y1
N30 M30
```

Use instead
-----------
On the same machine, this program:
```
; file: rfp.nc
N10 G74 Y1            (the master first)
N20 G74 Y2=1          (then the slave)
N30 M30
```

Reference
---------
P-AXIS-00070 (gantry master of a slave), P-AXIS-00074 (slave homed with its
master); TF5200 homing manual §2.2 and §2.3.3.4.5 (gantry coupling);
P-CHAN-00037 / P-CHAN-00038 (coupled pairs of the channel); LIS602, LIS514.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from ..core.diagnostics import Diagnostic, Severity

if TYPE_CHECKING:
    from ..machine.model import AxisWord, ChannelView, NamedAxis, Program

CODE = "LIS605"
NAME = "gantry-slave-alone"
FIX = "none"
SUMMARY = "Gantry slave homed before its master"


def check_program(program: Program, machine: ChannelView) -> Iterator[Diagnostic]:
    from ..machine.model import HomingBlock, SkippedBlock
    from .programcontext import defined, diagnostic, steps

    for step in steps(program, machine):
        block = step.block
        words: list[tuple[AxisWord | NamedAxis, int | None]]
        if isinstance(block, HomingBlock):
            words = [(word, int(word.value)) for word in block.words]
        elif isinstance(block, SkippedBlock) and block.homes:  # an order computed when the program runs
            words = [(word, None) for word in block.homes]
        else:
            continue
        order = {word.name: value for word, value in reversed(words)}
        for word, value in words:
            axis = machine.axes.get(word.name)
            master = axis.gantry_master if axis is not None else None
            if axis is None or master is None or not step.unhomed(master):
                continue
            # Homed together with its master or after it; with a computed order the order is not known.
            if master in order:
                step_of_master = order[master]
                if value is None or step_of_master is None or step_of_master <= value:
                    continue
            if master in order:
                why = f"in this block it homes at step {value}, before its master {master} (step {order[master]})"
            else:
                why = f"its master {master} is not homed before it"
            yield diagnostic(
                CODE,
                word.at,
                f"{word.name} is the gantry slave of {master} and {why}: home the slave together with its "
                "master or after it, so both sides of the gantry stay aligned",
                Severity.WARNING,
                defined(machine.axes[master]),
            )

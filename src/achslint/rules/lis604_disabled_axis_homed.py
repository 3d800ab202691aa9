"""
What
----
A `G74` block commands an axis whose homing type is `DISABLED`
(`kenngr.homing.homing_type`).

Why
---
`DISABLED` means the axis must never be homed: it has an absolute encoder and
its position is valid from power-up. The CNC answers a homing command for it
with an error (P-ERR-50686 or P-ERR-60313) and the homing program stops there;
the axes after it stay unhomed. `IGNORE_ABS_POS` is the setting for an absolute
axis that may appear in G74 and is passed over without an error.

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
kopf.achs_nr                 2
kopf.log_achs_name           C
kenngr.achs_typ              2
kenngr.antr_typ              8
kenngr.abs_pos_gueltig       1
kenngr.homing.homing_type    DISABLED
Ende
```
```
; file: rfp.nc
N10 G74 X1 C2
N20 M30
```

Use instead
-----------
On the same machine, this program:
```
; file: rfp.nc
N10 G74 X1            (C has an absolute encoder and is not homed)
N20 M30
```

Reference
---------
P-AXIS-00299 (homing_type DISABLED: P-ERR-50686 / P-ERR-60313 when commanded;
IGNORE_ABS_POS), P-AXIS-00014. The parameter page cites P-ERR-50685; the SDK's
message file has the "homing disabled" text under 50686 (50685 is a
synchronisation error), and the real file wins.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from ..core.diagnostics import Diagnostic, Related, Severity

if TYPE_CHECKING:
    from ..machine.model import ChannelView, Program

CODE = "LIS604"
NAME = "disabled-axis-homed"
FIX = "none"
SUMMARY = "G74 commands an axis whose homing is DISABLED"


def check_program(program: Program, machine: ChannelView) -> Iterator[Diagnostic]:
    from .programcontext import diagnostic, g74_words

    for words in g74_words(program):  # a G74 whose homing order is computed names its axes too
        for word in words:
            axis = machine.axes.get(word.name)
            if axis is None or axis.resolved.homing_type != "DISABLED":
                continue
            origin = axis.resolved.setting("kenngr.homing.homing_type")
            related: tuple[Related, ...] = ()
            if origin is not None and axis.list_path is not None:
                related = (
                    Related(
                        str(axis.list_path),
                        origin.line.number,
                        origin.line.path_column,
                        "kenngr.homing.homing_type",
                        "DISABLED here",
                    ),
                )
            yield diagnostic(
                CODE,
                word.at,
                f"{word.name} must not be homed (kenngr.homing.homing_type DISABLED): the CNC stops the "
                "program here with P-ERR-50686 / P-ERR-60313; leave it out of G74, or set IGNORE_ABS_POS "
                "if the program must name it",
                Severity.ERROR,
                related,
                "kenngr.homing.homing_type",
                "P-AXIS-00299",
            )

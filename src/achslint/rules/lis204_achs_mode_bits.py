"""
What
----
`kenngr.achs_mode` (P-AXIS-00015) with bits the CNC does not define, with
neither or both of LINEAR (0x1) and MODULO (0x4), or with MODULO_LINEAR
(0x400) but without MODULO.

Why
---
Exactly one of LINEAR and MODULO must be set; every other bit only adds to
it. With both or neither the axis mode is undefined, and an unknown bit is
usually a typo in a hex value (0x40001 instead of 0x400001).

Example
-------
```
kenngr.achs_mode               0x5
```

```
kenngr.achs_mode               0x401
```

Use instead
-----------
```
kenngr.achs_mode               0x1        ( linear
```

```
kenngr.achs_mode               0x404      ( modulo, modulo calculation for a conveyor
```

Reference
---------
P-AXIS-00015 bit table and note (1) in the TF5200 homing manual §4 (axis mode).
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from ..core.diagnostics import Diagnostic
    from .context import Context

CODE = "LIS204"
NAME = "achs-mode-bits"
FIX = "none"
SUMMARY = "Invalid combination of `kenngr.achs_mode` bits"

LINEAR, MODULO, MODULO_LINEAR = 0x1, 0x4, 0x400


def check(ctx: Context) -> Iterator[Diagnostic]:
    bits = ctx.catalogue.bitfields.get("P-AXIS-00015", {})
    known = 0
    for bit in bits:
        known |= bit
    achs_mode = ctx.catalogue.by_id.get("P-AXIS-00015")
    if achs_mode is None:
        return
    # the parameter has no index: its assignments are those of its path (old names included)
    for setting in ctx.analysis.by_canonical().get(achs_mode.path, ()):
        if not isinstance(setting.value, int):
            continue
        value = setting.value
        problems = []
        unknown = value & ~known
        if unknown:
            problems.append(f"bits {unknown:#x} are not defined")
        if value & LINEAR and value & MODULO:
            problems.append("both LINEAR (0x1) and MODULO (0x4) are set; set exactly one")
        elif not value & (LINEAR | MODULO):
            problems.append("neither LINEAR (0x1) nor MODULO (0x4) is set; set exactly one")
        if value & MODULO_LINEAR and not value & MODULO:
            problems.append("MODULO_LINEAR (0x400) only works together with MODULO (0x4)")
        if problems:
            names = [name for bit, name in sorted(bits.items()) if value & bit]
            line = setting.line
            start, end = ctx.value_span(line)
            yield ctx.report(
                CODE,
                line,
                f"`kenngr.achs_mode` {line.value} ({' | '.join(names) or 'no known bit'}): "
                + "; ".join(problems),
                column=start,
                end_column=end,
                setting=setting,
            )

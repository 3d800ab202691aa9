"""
What
----
The file starts with a UTF-8 byte-order mark (bytes EF BB BF).

Why
---
The CNC reads lists as plain ASCII/Latin-1 and reports an error when it finds
a byte-order mark; Windows editors add one when a file is saved as
"UTF-8 with BOM".

Example
-------
A list saved by an editor as "UTF-8 with BOM": the file starts with the bytes
EF BB BF, in front of its first line:

```
kopf.achs_nr          1
kopf.log_achs_name    X
```

Use instead
-----------
The same list saved as ANSI / Latin-1 or as UTF-8 without BOM (`achslint lint
--fix` removes the mark):

```
kopf.achs_nr          1
kopf.log_achs_name    X
```

Reference
---------
CNC error 21798 (UTF byte-order mark found; save the file as ASCII); list format facts §8.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from ..core.diagnostics import Diagnostic, Fix

if TYPE_CHECKING:
    from .context import Context

CODE = "LIS006"
NAME = "byte-order-mark"
FIX = "safe"
SUMMARY = "UTF-8 byte-order mark at the start of the file"


def check(ctx: Context) -> Iterator[Diagnostic]:
    if ctx.file.bom:
        first = ctx.file.lines[0]
        yield ctx.report(
            CODE,
            first,
            "the file starts with a UTF-8 byte-order mark, which the CNC rejects; save it without BOM",
            column=1,
            end_column=2,
            fix=Fix("safe", "remove the byte-order mark", remove_bom=True),
        )

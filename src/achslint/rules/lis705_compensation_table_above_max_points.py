"""
What
----
A table of an axis compensation list that its counts make larger than the
table memory its `max_points` reserves: `kw.ssfk.kw_nr_max` above
`kw.ssfk.max_points` (P-COMP-00059, default 1500), `kw.crosscomp.last_index`
+ 1 above `kw.crosscomp.max_points` (P-COMP-00060, default 1001),
(`last_index_master1` + 1) × (`last_index_master2` + 1) above
`kw.crosscomp2.max_points` (P-COMP-00061, default 10201), or
`frict_comp.table_entries` above `frict_comp.max_points` (P-COMP-00062,
default 20). A `max_points` of 0, or none written, is its default.

Why
---
`max_points` reserves the memory of a table when the list is loaded, and the
ranges of the counts are bounded by it: `last_index < max_points`
(P-COMP-00004), `kw_nr_max` below P-COMP-00059 (P-COMP-00020),
`table_entries ≤ max_points` (P-COMP-00042), and for plane compensation the
product of the two sizes may not exceed it (P-COMP-00061). A count outside
its range is a value the CNC does not accept. The table for `kw_nr_max`
writes `<`, while P-COMP-00059 is described as the largest number of
entries; a table of exactly `max_points` entries is not reported.

Example
-------
```
kopf.achs_nr                     1
kopf.log_achs_name               X
kw.ssfk.unit                     1
kw.ssfk.interval            200000
kw.ssfk.max_points               2          ( memory for two entries
kw.ssfk.kw_nr_max                3
kw.ssfk.table[0].pos             0
kw.ssfk.table[1].pos            12
kw.ssfk.table[2].pos            20
```

Use instead
-----------
Reserve the table memory the table needs:

```
kopf.achs_nr                     1
kopf.log_achs_name               X
kw.ssfk.unit                     1
kw.ssfk.interval            200000
kw.ssfk.max_points               3
kw.ssfk.kw_nr_max                3
kw.ssfk.table[0].pos             0
kw.ssfk.table[1].pos            12
kw.ssfk.table[2].pos            20
```

Reference
---------
P-COMP-00004, P-COMP-00010, P-COMP-00011, P-COMP-00020, P-COMP-00042 (the
counts and their ranges); P-COMP-00059 … P-COMP-00062 (max_points of each
table, with their defaults; P-COMP-00061: (last_index_master1 + 1) ×
(last_index_master2 + 1) ≤ max_points, and 0 or no value means the default).
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from ._comptables import tables
from ._kindvalues import unusable, written

if TYPE_CHECKING:
    from ..core.diagnostics import Diagnostic
    from .context import Context

CODE = "LIS705"
NAME = "compensation-table-above-max-points"
FIX = "none"
SUMMARY = "Compensation table larger than its max_points reserves"


def check(ctx: Context) -> Iterator[Diagnostic]:
    values = written(ctx.settings)
    for table in tables(values, unusable(ctx.settings)):
        limit, reserved = table.max_points(values)
        counts = [count for count in table.counts if count is not None]
        if not counts or table.size <= limit:
            continue
        zero = values.get(table.kind.max_points) if reserved is None else None  # `max_points 0`: the default
        origin = (
            f"`{table.kind.max_points}` = {limit}"
            if reserved is not None
            else f"`{table.kind.max_points}` = 0, which means its default {limit}"
            if zero is not None
            else f"`{table.kind.max_points}` is not set, so its default {limit} applies"
        )
        shown = reserved if reserved is not None else zero
        related = [ctx.related(shown, "the reserved size")] if shown is not None else []
        sizes = " × ".join(str(size) for size in table.sizes)
        total = f"{sizes} = {table.size}" if len(table.sizes) > 1 else str(table.size)
        start, end = ctx.value_span(counts[0].line)
        yield ctx.report(
            CODE,
            counts[0].line,
            f"{table.counted('make')} the table {total} entries large, but {origin}: the count is outside its "
            f"range; raise {table.kind.max_points} to {table.size} at least, or make the table smaller",
            column=start,
            end_column=end,
            setting=counts[0],
            related=[*related, *(ctx.related(count, "a count") for count in counts[1:])],
        )

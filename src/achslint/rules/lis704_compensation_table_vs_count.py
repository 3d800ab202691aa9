"""
What
----
A table of an axis compensation list whose entries do not match the count
that sizes it:

- leadscrew error compensation: `kw.ssfk.kw_nr_max` (P-COMP-00020) entries
  `kw.ssfk.table[i]`, each with `pos` (P-COMP-00023), also `neg`
  (P-COMP-00024) when `kw.ssfk.bilateral` is 1, also `setpoint`
  (P-COMP-00025) when `kw.ssfk.interval` is 0 (points not equidistant);
- cross compensation: `kw.crosscomp.table[0]` up to `kw.crosscomp.last_index`
  (P-COMP-00004), each with `setpoint` and `correction`;
- plane compensation: `kw.crosscomp2.table[j][i].correction` (P-COMP-00016)
  for j up to `last_index_master2` and i up to `last_index_master1`
  (P-COMP-00011, P-COMP-00010);
- friction compensation: `frict_comp.table_entries` (P-COMP-00042) entries
  `frict_comp.table[i]`, each with `in` and `out`.

An entry beyond the count is reported at its line; the entries the count
includes and the list does not write are reported together at the count.

Why
---
The count says how large the table is. An entry beyond it lies outside the
table the count describes; an entry inside it that the list does not write
keeps its default 0, so the compensation there is 0 or, for a missing
interpolation point, the point lies at position 0. A point added or removed
without changing the count, or a count copied from another axis, is the usual
cause. What the CNC does with an entry beyond the count is not documented.

Example
-------
```
kopf.achs_nr                 1
kopf.log_achs_name           X
kw.ssfk.unit                 1
kw.ssfk.interval        200000
kw.ssfk.kw_nr_max            3
kw.ssfk.table[0].pos         0
kw.ssfk.table[1].pos        12
kw.ssfk.table[2].pos        20
kw.ssfk.table[3].pos        17          ( a fourth point, the count not raised
```

Use instead
-----------
```
kopf.achs_nr                 1
kopf.log_achs_name           X
kw.ssfk.unit                 1
kw.ssfk.interval        200000
kw.ssfk.kw_nr_max            4
kw.ssfk.table[0].pos         0
kw.ssfk.table[1].pos        12
kw.ssfk.table[2].pos        20
kw.ssfk.table[3].pos        17
```

Reference
---------
P-COMP-00004 (last index of the cross compensation table), P-COMP-00010 /
P-COMP-00011 (last indices of the plane compensation table; its index j
belongs to master axis 2, P-COMP-00016), P-COMP-00018 (interval 0: each
interpolation point is given), P-COMP-00020 (number of leadscrew compensation
values), P-COMP-00021 (bilateral), P-COMP-00023 … P-COMP-00025 (the table's
members, default 0), P-COMP-00042 (friction compensation entries).
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from ._comptables import tables
from ._kindvalues import shown, unusable, written

if TYPE_CHECKING:
    from ..core.diagnostics import Diagnostic
    from .context import Context

CODE = "LIS704"
NAME = "compensation-table-vs-count"
FIX = "none"
SUMMARY = "Compensation table entry beyond its count, or an entry the count includes not written"


def check(ctx: Context) -> Iterator[Diagnostic]:
    values = written(ctx.settings)
    for table in tables(values, unusable(ctx.settings)):
        if table.size > table.max_points(values)[0]:
            continue  # a count out of its range: LIS705 (what the CNC makes of the table is not known)
        counts = [count for count in table.counts if count is not None]
        for indices, members in sorted(table.written.items()):
            if table.inside(indices):
                continue
            for setting in sorted(members.values(), key=lambda setting: setting.line.number):
                start, end = ctx.path_span(setting.line)
                yield ctx.report(
                    CODE,
                    setting.line,
                    f"`{setting.canonical}` lies outside the table: {table.counted('give')} it the entries "
                    f"{table.span()}; raise the count if the entry is meant, or remove it",
                    column=start,
                    end_column=end,
                    setting=setting,
                    related=[ctx.related(count, "the count") for count in counts],
                )
        missing = list(table.missing(values))
        if not missing:
            continue
        # at the count, or at the table's first line when no count is written
        where = (
            counts[0]
            if counts
            else min(
                (setting for members in table.written.values() for setting in members.values()),
                key=lambda setting: setting.line.number,
            )
        )
        start, end = ctx.value_span(where.line) if counts else ctx.path_span(where.line)
        yield ctx.report(
            CODE,
            where.line,
            f"{table.counted('give')} the table the entries {table.span()}, but the list does not write "
            f"{shown(missing)}: the CNC takes the default 0 for each; write the missing entries, or set the "
            "count to the entries there are",
            column=start,
            end_column=end,
            setting=where,
        )

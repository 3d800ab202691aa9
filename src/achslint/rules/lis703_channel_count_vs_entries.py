"""
What
----
A count in a channel list that differs from the entries it counts: the
number of axes of the axis group `gruppe[0].achs_anzahl` (P-CHAN-00003)
against the path axes the list defines (slots `gruppe[0].achse[j]` with a
logical axis number other than 0, P-CHAN-00035), or the number of spindles
`spdl_anzahl` (P-CHAN-00082) against the spindles it enters (`spindel[i]`
with a logical axis number, P-CHAN-00036). The slots are counted as the CNC
loads them: with the default channel list (`default_sda_mds`) underneath when
a start-up list names one. A count the channel list does not write is not
judged: the default channel list may set it.

Why
---
The manual asks for the count to match: `achs_anzahl` counts the axes that
are defined (an empty slot in between is not counted), and `spdl_anzahl`
must equal the spindles entered under `spindel[i]`. What the CNC does with
a count that says otherwise is not documented; a count not raised when an
axis or a spindle was added, or not lowered when one was removed, is the
usual cause, and the axis that is not counted may be missing from the channel.

Example
-------
```
# file: sda_mds1.lis
gruppe[0].achs_anzahl             2          ( three axes are defined
gruppe[0].achse[0].bezeichnung    X
gruppe[0].achse[0].log_achs_nr    1
gruppe[0].achse[1].bezeichnung    Y
gruppe[0].achse[1].log_achs_nr    2
gruppe[0].achse[2].bezeichnung    Z
gruppe[0].achse[2].log_achs_nr    3
```

Use instead
-----------
The count of the axes the list defines:

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
P-CHAN-00003 (gruppe[i].achs_anzahl: only defined axes are counted, gaps are
not), P-CHAN-00082 (spdl_anzahl: must equal the spindles entered),
P-CHAN-00035 / P-CHAN-00036 (logical axis numbers of path axes and
spindles). The manuals name no CNC error for a count that does not match.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from ._kindvalues import Slot, shown, slots, whole, written

if TYPE_CHECKING:
    from ..core.diagnostics import Diagnostic
    from .context import Context

CODE = "LIS703"
NAME = "channel-count-vs-entries"
FIX = "none"
SUMMARY = "achs_anzahl or spdl_anzahl differs from the axes or spindles the channel list defines"


def _counted(every: list[Slot]) -> dict[str, tuple[str, list[Slot]]]:
    """Each count's path -> (what it counts, the slots that define one)."""
    groups: dict[str, tuple[str, list[Slot]]] = {}
    for slot in every:
        if slot.logical_number is None:
            continue  # an empty slot (log_achs_nr 0 or none): not counted
        if slot.spindle:
            groups.setdefault("spdl_anzahl", ("spindles", []))[1].append(slot)
        else:
            group = slot.path.split(".", 1)[0]
            groups.setdefault(f"{group}.achs_anzahl", ("path axes", []))[1].append(slot)
    return groups


def check(ctx: Context) -> Iterator[Diagnostic]:
    values = written(ctx.settings)
    # the slots as the CNC loads them: the default channel list's underneath, this list's on top
    groups = _counted(slots({**written(ctx.default_settings), **values}))
    own = {id(setting) for setting in ctx.settings}
    counts = [path for path in values if path == "spdl_anzahl" or path.endswith("].achs_anzahl")]
    for path in counts:
        count = whole(values[path])
        what, defined = groups.get(path, ("spindles" if path == "spdl_anzahl" else "path axes", []))
        if count is None or count == len(defined):
            continue
        line = values[path].line
        start, end = ctx.value_span(line)
        names = shown([slot.label for slot in defined])
        entered = f"defines {len(defined)}: {names}" if defined else "defines none"
        yield ctx.report(
            CODE,
            line,
            f"`{path}` = {count}, but the channel list {entered}; the count must equal the {what} the list "
            f"defines: set it to {len(defined)}, or add or remove the {what} that are meant",
            column=start,
            end_column=end,
            setting=values[path],
            related=[
                ctx.related(slot.number, f"a defined {what[:-1]}")
                for slot in defined[:6]
                if slot.number and id(slot.number) in own  # a slot of the default list: not in this file
            ],
        )

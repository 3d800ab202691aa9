"""
What
----
Two axis lists of the same machine use the same logical axis number
`kopf.achs_nr`. A machine is the lists of one start-up list (`hochlauf.lis`,
`achs_mds[i]`) or, without one, the `achsmds*.lis` of one folder.

In a TwinCAT export (`.xti`, `.xml`, `.tsproj`) whose axis lists sit in tree
items (`<ItemName>`, `<PathName>`, `<ItemId>`, `<ObjectId>` around the
`<IsgAxisDef>`), the rule compares the number TwinCAT gives each axis item,
its `ItemId`, instead of the `kopf.achs_nr` embedded in the item: two tree
items with the same `ItemId` are reported, and the message names both items
(`TICC^CNC^Axes^Axis_Y`). XML without tree items is compared by its
`kopf.achs_nr`, like a list file, with the other lists that have no tree item.

Why
---
The logical axis number identifies the axis everywhere in the CNC (channel
assignment, gantry coupling, PLC interface). Two lists with the same number
usually come from copying a list and forgetting to renumber it: one axis then
silently takes over the other's parameters.

In a TwinCAT project the start-up list is not written by hand: its
`achs_mds[i]` entries are set by TwinCAT (P-STUP-00015, "TwinCAT: automatic
entry"), and the logical numbers of a TwinCAT CNC run "normally [1, gNrAX]".
Exports of working projects embed one template header in every axis item
(`kopf.achs_nr 1`, `kopf.log_achs_name X_Achse`) while the items are numbered
1, 2, 3, ...; read literally, such a project would abort its start-up (a
logical number twice is error 1001121). What the exports show is that
TwinCAT, not the embedded header, decides the number. Beckhoff's documentation
does not state this outright, so achslint says which identity it compared.
Two tree items with one `ItemId` are a real duplicate: the same axis exported
twice (`Axis_Y.xti` beside `Axis_Y - Copy.xti`), or an id edited by hand.

A template header repeated across distinct tree items is not reported at all,
not even as `info`: every unchanged export looks like that, a note on each axis
of a 20-axis project would ask for nothing a user can do (TwinCAT writes the
header), and the duplicate that matters is still found by its `ItemId`.

Example
-------
```
# file: achsmds1.lis
kopf.achs_nr          1
kopf.log_achs_name    X
```

```
# file: achsmds2.lis
kopf.achs_nr          1          ( copied from achsmds1.lis
kopf.log_achs_name    Y
```

Use instead
-----------
With achsmds1.lis as it is, give achsmds2.lis its own number:

```
# file: achsmds2.lis
kopf.achs_nr          2
kopf.log_achs_name    Y
```

In a TwinCAT export, keep one file per tree item: export the project again
from TwinCAT rather than copying an axis file.

Reference
---------
P-AXIS-00016 (logical axis number, unique per machine); P-STUP-00015
(`achs_mds[i]`, entered automatically in TwinCAT systems); HLI axis number
("In TwinCAT normally [1, gNrAX]"); diagnosis ID 1001121 (axis cannot be
configured, start-up aborted). The override of `kopf.achs_nr` by TwinCAT is
inferred from exports, not documented.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING, Any

from ..core.diagnostics import Diagnostic
from ..machine.identity import repeated_identities, tree_items
from ..machine.startup import repeated_values

if TYPE_CHECKING:
    from ..machine.resolved import Machine
    from ..machine.startup import Member

CODE = "LIS501"
NAME = "duplicate-axis-number"
FIX = "none"
PARAMETERS = ("kopf.achs_nr",)  # parameters this rule reads
SUMMARY = "Two axis lists of a machine with the same logical axis number"


def check_machine(machine: Machine) -> Iterator[Diagnostic]:
    members = machine.members
    items, lists = tree_items(members)
    yield from repeated_values(
        CODE,
        lists,
        "achs_nr",
        "kopf.achs_nr",
        lambda number, note, first: (
            f"logical axis number kopf.achs_nr {number}{note} is also used by {first}; "
            "every axis of a machine needs its own"
        ),
    )
    yield from repeated_identities(CODE, items, lambda identity: identity["item_id"], "ItemId", _says)


def _says(number: object, identity: dict[str, Any], first: Member) -> str:
    compared = "(compared: the tree items' ItemId, not the kopf.achs_nr embedded in them)"
    if identity["item"] == first[1]["identity"]["item"]:
        return f"TwinCAT tree item {identity['item']} (ItemId {number}) is exported twice, also in {first[0]}; keep one export of it {compared}"
    return (
        f"TwinCAT tree items {identity['item']} and {first[1]['identity']['item']} (in {first[0]}) both have "
        f"ItemId {number}; TwinCAT numbers each axis item once, so one axis is exported twice or an id was "
        f"edited {compared}"
    )

"""
What
----
Two axis lists of the same machine use the same axis name
`kopf.log_achs_name`.

In a TwinCAT export whose axis lists sit in tree items, the rule compares the
names TwinCAT uses instead of the embedded `kopf.log_achs_name`: the item's
place in the tree (`<PathName>`, `TICC^CNC^Axes^Axis_X`; `<ItemName>` when
there is no path), and the name the item gives the axis in its channel
(`<DefaultProgName>` within one `<DefaultChannel>`). XML without tree items is
compared by its `kopf.log_achs_name` with the other lists that have none.

Why
---
Programs address axes by name (`G01 X…`); two axes with one name make the
channel configuration ambiguous, and the second one is not reachable under
the name you expect.

In TwinCAT the embedded `kopf.log_achs_name` means little: P-AXIS-00297 only
matters for name conflicts in axis exchange, the name programs use comes from
the channel (P-CHAN-00006), and real exports embed the same template name
(`X_Achse`) in every axis item, so it is not compared between tree items (see
LIS501 for why the template header is not reported at all). Two items with one
`PathName` are one axis exported twice; two axes of one channel with the same
`DefaultProgName` are what NC programs of that channel could not tell apart
(that these elements place the axis in its channel is read from the exports;
Beckhoff does not document the XML).

Example
-------
```
# file: achsmds1.lis
kopf.achs_nr          1
kopf.log_achs_name    X
```

```
# file: achsmds3.lis
kopf.achs_nr          3
kopf.log_achs_name    X          ( copied from achsmds1.lis
```

Use instead
-----------
With achsmds1.lis as it is, give achsmds3.lis its own name:

```
# file: achsmds3.lis
kopf.achs_nr          3
kopf.log_achs_name    Z
```

Reference
---------
P-AXIS-00297 (default axis name; no meaning beside axis exchange), P-CHAN-00006
(axis name in the channel).
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

CODE = "LIS502"
NAME = "duplicate-axis-name"
FIX = "none"
PARAMETERS = ("kopf.log_achs_name",)  # parameters this rule reads
SUMMARY = "Two axis lists of a machine with the same axis name"


def _named_in_channel(identity: dict[str, Any]) -> tuple[int, str] | None:
    """(channel, name) of a tree item that gives its axis a name in a channel, else None."""
    if identity["channel"] is None or not identity["program_name"]:
        return None
    return identity["channel"], identity["program_name"]


def _tree_name(identity: dict[str, Any]) -> str | None:
    """The item's place in the TwinCAT tree: its PathName, else its ItemName."""
    name: str | None = identity["path"] or identity["name"]
    return name


def _one_per_item(items: list[Member]) -> list[Member]:
    """The first member of each tree item: an item exported twice is reported once (by its PathName), and its
    name in the channel is no second axis's name."""
    seen: set[str] = set()
    first = []
    for member in items:
        name = _tree_name(member[1]["identity"])
        if name is None or name not in seen:
            first.append(member)
        if name is not None:
            seen.add(name)
    return first


def check_machine(machine: Machine) -> Iterator[Diagnostic]:
    members = machine.members
    items, lists = tree_items(members)
    yield from repeated_values(
        CODE,
        lists,
        "name",
        "kopf.log_achs_name",
        lambda name, note, first: (
            f"axis name kopf.log_achs_name `{name}`{note} is also used by {first}; give each axis its own name"
        ),
    )
    yield from repeated_identities(
        CODE,
        items,
        _tree_name,
        "PathName",
        lambda item, identity, first: (
            f"TwinCAT tree item {item} is exported twice, also in {first[0]}; keep one export of it "
            "(compared: the tree items' PathName, not the kopf.log_achs_name embedded in them)"
        ),
    )
    yield from repeated_identities(
        CODE,
        _one_per_item(items),
        _named_in_channel,
        "DefaultProgName",
        lambda named, identity, first: (
            f"TwinCAT tree items {identity['item']} and {first[1]['identity']['item']} (in {first[0]}) are both "
            f"`{identity['program_name']}` in channel {identity['channel']}, which NC programs of that channel "
            "cannot tell apart; give each its own DefaultProgName (compared: DefaultChannel and "
            "DefaultProgName, not the kopf.log_achs_name embedded in them)"
        ),
    )

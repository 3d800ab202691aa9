"""The identity TwinCAT gives an axis, as the machine rules compare it (LIS501, LIS502).

A list read from a TwinCAT tree item carries `identity` in its machine summary (`xmlinput.TreeItem.identity`:
"item", "name", "path", "item_id", "object_id", "channel", "index", "program_name" and the XML "positions" of
the elements they come from). Exports of one project may embed the same template header in every axis, so for
these members the rules compare the tree items, and the header only among the lists without one. The gantry
rules (LIS316, LIS503, LIS507, LIS510, LIS511) find a slave's master by the header's `kopf.achs_nr`: a tree
item whose header number another tree item repeats carries a template number, not the axis's, so they leave
it out (`numbered`) rather than pair axes by a number TwinCAT replaces.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Callable, Iterator
from typing import Any

from ..core.diagnostics import Diagnostic, Related, Severity
from .startup import Member

Identity = dict[str, Any]


def tree_items(members: list[Member]) -> tuple[list[Member], list[Member]]:
    """The members that carry a TwinCAT tree item, and the others."""
    return [m for m in members if m[1].get("identity")], [m for m in members if not m[1].get("identity")]


def numbered(members: list[Member]) -> list[Member]:
    """The members whose `kopf.achs_nr` is the axis's number: every list without a TwinCAT tree item, and the
    tree items whose embedded header number no other tree item repeats."""
    items = Counter(m[1].get("achs_nr") for m in members if m[1].get("identity"))
    return [m for m in members if not m[1].get("identity") or items[m[1].get("achs_nr")] == 1]


def repeated_identities(
    code: str,
    members: list[Member],
    value: Callable[[Identity], object],
    element: str,
    says: Callable[[object, Identity, Member], str],
) -> Iterator[Diagnostic]:
    """A warning for every tree item whose `value` an earlier one already had (None, "" and 0 are no value).

    The finding points at the XML `element` that holds the value (the item's first element read when it has
    none) and back at the earlier item's; `says(value, identity, earlier)` words it.
    """
    first: dict[object, Member] = {}
    for member in members:
        identity = member[1]["identity"]
        found = value(identity)
        if found in (None, "", 0):
            continue
        earlier = first.setdefault(found, member)
        if earlier is member:
            continue
        line, column = _at(identity, element)
        back_line, back_column = _at(earlier[1]["identity"], element)
        yield Diagnostic(
            member[0],
            line,
            column,
            line,
            column + 1,
            code,
            Severity.WARNING,
            says(found, identity, earlier),
            related=(Related(earlier[0], back_line, back_column, element, "first use"),),
        )


def _at(identity: Identity, element: str) -> tuple[int, int]:
    positions: dict[str, tuple[int, int]] = identity["positions"]
    return positions.get(element) or next(iter(positions.values()), (1, 1))

"""What the cross-list machine rules (LIS512–LIS518) share: the machine's axis lists by logical axis number,
whether every axis list was read, the counts and the entries they count (`zahl_mds`, `zahl_kw`), and a
finding at a channel list's value. (The channel lists themselves come from `Machine.channel_lists`, read
once per machine with the default channel list underneath.)"""

from __future__ import annotations

import os
from typing import TYPE_CHECKING

from ..core.diagnostics import Diagnostic, Related, Severity
from ..machine.startup import MAX_COUNT, entry_index

if TYPE_CHECKING:
    from ..machine.channel import ChannelAxis
    from ..machine.startup import Member, Startup

# A count's entries (`zahl_mds` counts `achs_mds[i]`) and the parameter id of each, for messages.
COUNTED = {
    "zahl_mds": ("achs_mds", "P-STUP-00014", "P-STUP-00015"),
    "zahl_kw": ("achs_kw", "P-STUP-00016", "P-STUP-00017"),
}
MAX_ENTRIES = MAX_COUNT["zahl_mds"]  # zahl_mds and zahl_kw range 1 ... 32 (P-STUP-00014, P-STUP-00016)


def by_number(members: list[Member]) -> dict[int, Member]:
    """The machine's axis lists by `kopf.achs_nr`, the first list for a repeated number (LIS501's)."""
    found: dict[int, Member] = {}
    for member in members:
        number = member[1].get("achs_nr")
        if isinstance(number, int) and not isinstance(number, bool):
            found.setdefault(number, member)
    return found


index = entry_index  # the index of an entry like `achs_mds[3]` (3)


def every_axis_list_read(startup: Startup, members: list[Member]) -> bool:
    """Whether each axis list the CNC loads (the entries below `zahl_mds`) was read as a member of the
    machine: when one is missing or unreadable (LIS504, or that list's own error), its logical axis number is
    not known. An entry beyond the count is never read (LIS516), so it leaves no number unknown."""
    read = {os.path.realpath(name) for name, _ in members}
    return all(
        entry.path is not None and os.path.realpath(entry.path) in read for entry in startup.loaded_axes()
    )


def at_channel_axis(
    code: str, axis: ChannelAxis, severity: Severity, message: str, related: list[Related] | None = None
) -> Diagnostic:
    """A finding on the name of a channel list's slot (its number's line when the name is missing)."""
    end = axis.at.end_column or axis.at.column + len(axis.name)
    return Diagnostic(
        axis.at.path,
        axis.at.line,
        axis.at.column,
        axis.at.line,
        end,
        code,
        severity,
        message,
        related=tuple(related or ()),
    )


def at_member(member: Member, where: str, parameter: str, note: str) -> Related:
    """A related location in an axis list: the line of `where` (a summary key like `gantry_at`), or the
    list's logical axis number, or its first line."""
    name, info = member
    line, column = info.get(where) or info.get("achs_nr_at") or (1, 1)
    return Related(name, line, column, parameter, note)


def axis_words(axis: ChannelAxis) -> str:
    """How a channel slot is named in messages: `gruppe[0].achse[2] (Z, logical axis 7)`."""
    return f"{axis.slot} (`{axis.name}`, logical axis {axis.logical_number})"

"""
What
----
A start-up list whose number of channels `kanal_anzahl` (P-STUP-00001) does
not match the lists it names per channel: a channel below the count without
a channel list `sda_mds[i]` (P-STUP-00009), or a per-channel entry for a
channel the count leaves out: `sda_mds[i]`, tool data `werkz_data[i]`
(P-STUP-00010), zero offsets `nullp_data[i]` (P-STUP-00011) or clamp position
offsets `pzv_data[i]` (P-STUP-00012) with an index not below the count. An
index of 12 or above is told that no count reaches it (`kanal_anzahl` is at
most 12), not asked to raise the count beyond its range. The
index of these entries is the channel's (0 for the first channel). A start-up
list that does not write `kanal_anzahl` is not judged, nor one whose count is
out of range (LIS202); missing channel lists are reported only when the
start-up list names a channel list at all (one that names none may be the
axis part of a start-up list, kept for its axis lists). The start-up list is judged as the machine it
defines, with LIS516 and LIS517, which compare its counts `zahl_mds` and
`zahl_kw` with their entries.

Why
---
The manual asks for `kanal_anzahl` to match the channels that are configured,
and each channel takes its channel parameters, tool data, zero offsets and
clamp position offsets from the entries with its index. A channel without a
channel list has no axes or spindles configured, and a list named for a
channel beyond the count belongs to no configured channel. What the CNC does
in either case is not documented; a channel added or removed in one place
and not in the other is the usual cause. TwinCAT writes these entries
itself; the finding is for start-up lists kept by hand.

Example
-------
```
# file: hochlauf.lis
kanal_anzahl      2                  ( sda_mds[1] is not named
zahl_mds          2
achs_mds[0]       ./achsmds1.lis
achs_mds[1]       ./achsmds2.lis
sda_mds[0]        ./sda_mds1.lis
```

```
# file: achsmds1.lis
kopf.achs_nr          1
kopf.log_achs_name    X
```

```
# file: achsmds2.lis
kopf.achs_nr          2
kopf.log_achs_name    Y
```

```
# file: sda_mds1.lis
gruppe[0].achs_anzahl             1
gruppe[0].achse[0].bezeichnung    X
gruppe[0].achse[0].log_achs_nr    1
```

Use instead
-----------
A channel list for every channel, the second one with the Y axis:

```
# file: hochlauf.lis
kanal_anzahl      2
zahl_mds          2
achs_mds[0]       ./achsmds1.lis
achs_mds[1]       ./achsmds2.lis
sda_mds[0]        ./sda_mds1.lis
sda_mds[1]        ./sda_mds2.lis
```

```
# file: sda_mds2.lis
gruppe[0].achs_anzahl             1
gruppe[0].achse[0].bezeichnung    Y
gruppe[0].achse[0].log_achs_nr    2
```

Reference
---------
P-STUP-00001 (kanal_anzahl, 1 … 12: must correspond to the configured
channels), P-STUP-00009 / P-STUP-00010 / P-STUP-00011 / P-STUP-00012 (the list
files of each channel, i = 0 … 11). The manuals name no CNC error for a count
that does not match.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from ..core.diagnostics import Diagnostic, Severity
from ..machine.startup import MAX_COUNT
from ..syntax.parser import path_pattern
from ._kindvalues import at_setting, related_at, shown, startup_settings, whole, written

if TYPE_CHECKING:
    from ..machine.resolved import Machine

CODE = "LIS522"
NAME = "channel-count-vs-lists"
FIX = "none"
SUMMARY = "kanal_anzahl differs from the channel lists, or a list is named for a channel beyond it"

MAX_CHANNELS = MAX_COUNT["kanal_anzahl"]  # 1 ... 12 (P-STUP-00001): sda_mds[11] is the last channel's list
PER_CHANNEL = {
    "sda_mds[i]": "channel list",
    "werkz_data[i]": "tool data list",
    "nullp_data[i]": "zero offset list",
    "pzv_data[i]": "clamp position offset list",
}


def _channels(count: int) -> str:
    if count <= 0:
        return "no channel"
    return "the first channel (index 0) only" if count == 1 else f"channels 0 … {count - 1}"


def check_machine(machine: Machine) -> Iterator[Diagnostic]:
    startup = machine.startup
    settings = startup_settings(machine)
    values = written(settings) if settings is not None else None
    setting = values.get("kanal_anzahl") if values is not None else None
    count = whole(setting)
    if values is None or setting is None or count is None:
        return
    name = str(startup.path) if startup is not None else ""
    channel_lists: set[int] = set()
    for path, entry in values.items():
        pattern, indices = path_pattern(path)
        what = PER_CHANNEL.get(pattern)
        if what is None:
            continue
        if pattern == "sda_mds[i]":
            channel_lists.add(indices[0])
        if indices[0] < count:
            continue
        yield at_setting(
            CODE,
            name,
            entry,
            Severity.WARNING,
            f"`{path}` names the {what} of channel index {indices[0]}, but `kanal_anzahl` = {count} "
            f"configures {_channels(count)}: "
            + (
                f"raise kanal_anzahl to {indices[0] + 1} if the channel is meant, or remove the entry"
                if indices[0] < MAX_CHANNELS
                else f"no kanal_anzahl reaches it (kanal_anzahl is at most {MAX_CHANNELS}, so index "
                f"{MAX_CHANNELS - 1} is the last channel's): give it the index of a channel below "
                f"{MAX_CHANNELS}, or remove the entry"
            ),
            [related_at(name, setting, "the number of channels")],
            value=False,
        )
    # a start-up list that names no channel list at all (the axis part of one, kept for the axis lists) is
    # not told it misses them all
    missing = [f"sda_mds[{index}]" for index in range(count) if index not in channel_lists]
    if missing and channel_lists:
        yield at_setting(
            CODE,
            name,
            setting,
            Severity.WARNING,
            f"`kanal_anzahl` = {count} configures {_channels(count)}, but the start-up list does not name "
            f"{shown(missing)}: each channel needs its channel list; name one, or lower kanal_anzahl to the "
            "channels there are",
        )

"""
What
----
A zero offset list `nullp_data[i]` (P-STUP-00011) or a clamp position offset
list `pzv_data[i]` (P-STUP-00012) with an entry for an axis its channel does
not have: `np_grp[g].achse[j].*` (P-ZERO-00003, P-ZERO-00004) or
`pzv_grp[g].achse[j].versatz` (P-CLMP-00001) where the channel list of the
same channel, `sda_mds[i]`, defines no path axis in slot
`gruppe[0].achse[j]` (a logical axis number other than 0, P-CHAN-00035). The
channel list is read with the default channel list underneath; a channel
without a readable channel list is not judged (LIS504, LIS522).

Why
---
The index `j` of an offset is the channel-internal axis index: the offset
of `achse[j]` applies to the path axis of the channel list's slot
`gruppe[0].achse[j]`. An offset for a slot the channel does not define
belongs to no axis, so it never moves anything, while the axis it was meant
for keeps offset 0. An axis removed from the channel list, or offsets copied
from a channel with more axes, is the usual cause. What the CNC does with such
an entry is not documented.

Example
-------
```
# file: hochlauf.lis
kanal_anzahl      1
zahl_mds          2
achs_mds[0]       ./achsmds1.lis
achs_mds[1]       ./achsmds2.lis
sda_mds[0]        ./sda_mds1.lis
nullp_data[0]     ./nullp_d1.lis
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
gruppe[0].achs_anzahl             2
gruppe[0].achse[0].bezeichnung    X
gruppe[0].achse[0].log_achs_nr    1
gruppe[0].achse[1].bezeichnung    Y
gruppe[0].achse[1].log_achs_nr    2
```

```
# file: nullp_d1.lis
np_grp[1].achse[0].versch     1255000
np_grp[1].achse[1].versch      -40000
np_grp[1].achse[2].versch    -3000000       ( the channel has no third axis
```

Use instead
-----------
Offsets only for the axes of the channel:

```
# file: nullp_d1.lis
np_grp[1].achse[0].versch     1255000
np_grp[1].achse[1].versch      -40000
```

Reference
---------
P-ZERO-00003 / P-ZERO-00004 and P-CLMP-00001 (offsets per axis `achse[j]`,
j the channel-internal axis index), P-CHAN-00035 (the path axes of a channel),
P-STUP-00009 / P-STUP-00011 / P-STUP-00012 (the lists of channel i). The
manuals name no CNC error for an offset of an axis the channel does not have.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from ..catalogue.kinds import CLAMP_OFFSETS, ZERO_OFFSETS, Kind
from ..core.diagnostics import Diagnostic, Severity
from ..core.files import shown_path
from ..syntax.parser import path_pattern
from ._crosslist import index
from ._kindvalues import at_setting, loaded_settings, shown

if TYPE_CHECKING:
    from ..machine.resolved import Machine
    from ..machine.startup import StartupEntry

CODE = "LIS521"
NAME = "offset-for-missing-channel-axis"
FIX = "none"
SUMMARY = "Zero or clamp position offset for an axis the channel list does not define"

# start-up entry pattern -> (the list in words, its kind, the group of its per-axis entries)
OFFSET_LISTS: dict[str, tuple[str, Kind, str]] = {
    "nullp_data[i]": ("zero offset list", ZERO_OFFSETS, "np_grp[i].achse[i]."),
    "pzv_data[i]": ("clamp position offset list", CLAMP_OFFSETS, "pzv_grp[i].achse[i]."),
}


def _channel_entry(machine: Machine, channel: int) -> StartupEntry | None:
    """The entry `sda_mds[channel]` (the later one when two name it) of a channel `kanal_anzahl` counts."""
    startup = machine.startup
    entries = [entry for entry in startup.loaded_channels() if index(entry) == channel] if startup else []
    return entries[-1] if entries else None


def _path_axes(machine: Machine, entry: StartupEntry) -> dict[int, str] | None:
    """The path axes of a channel list by channel-internal axis index (the slot `gruppe[0].achse[j]`), in
    words; None when it cannot be read."""
    found = machine.channel(entry)
    if found is None:
        return None
    axes = {}
    for axis in found.axes:
        pattern, indices = path_pattern(axis.slot)
        if pattern == "gruppe[i].achse[i]" and indices[0] == 0:
            axes[indices[1]] = f"{axis.slot} (`{axis.name}`)"
    return axes


def check_machine(machine: Machine) -> Iterator[Diagnostic]:
    startup = machine.startup
    if startup is None:
        return
    for entry in startup.loaded_others():  # a channel beyond kanal_anzahl: never loaded (LIS522)
        pattern, _ = path_pattern(entry.key)
        if pattern not in OFFSET_LISTS or entry.path is None:
            continue
        what, kind, group = OFFSET_LISTS[pattern]
        channel = _channel_entry(machine, index(entry))
        axes = _path_axes(machine, channel) if channel is not None else None
        if channel is None or axes is None:
            continue
        settings = loaded_settings(machine, entry, what, kind)
        for setting in settings or []:
            shape, indices = path_pattern(setting.canonical or "")
            if not shape.startswith(group) or indices[1] in axes:
                continue
            defined = shown(list(axes.values())) if axes else "none"
            yield at_setting(
                CODE,
                shown_path(entry.path),
                setting,
                Severity.WARNING,
                f"`{setting.canonical}` is for axis index {indices[1]} of channel index {index(entry)}, but "
                f"that channel's list `{channel.raw}` defines no path axis in slot "
                f"gruppe[0].achse[{indices[1]}] (its path axes: {defined}): the {what[:-5]} belongs to no "
                "axis; move it to the index of the axis it is meant for, or remove it",
                value=False,
            )

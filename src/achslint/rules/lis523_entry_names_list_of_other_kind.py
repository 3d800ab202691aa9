"""
What
----
A start-up list entry that names a list whose content is clearly of another
kind: `achs_mds[i]` (P-STUP-00015) naming a channel list, `sda_mds[i]`
(P-STUP-00009) naming an axis list — two entries swapped while editing the
start-up list by hand —, a tool data entry `werkz_data[i]` (P-STUP-00010)
naming a zero offset list, and so on. Every entry the CNC loads is checked:
the axis lists below `zahl_mds` (P-STUP-00014), the default lists
`default_achs_mds` (P-STUP-00035) and `default_sda_mds` (P-STUP-00034), the
channel lists and the other per-channel lists below `kanal_anzahl`
(P-STUP-00001), the compensation lists below `zahl_kw` (P-STUP-00016), and
the other lists the start-up list names (`hand_mds`, `rtconf_lis` ...).

The file is read as the machine reads it (in the editor, its open buffer),
and its kind is told from its content the way lint tells the kind of a list
no entry names: only clear evidence counts — at least three parameter ids of
the kind in comments, or at least three parameters of its catalogue that make
up half of the list or more (an axis list: three axis parameters). A list too
short to show its kind, or with names of several kinds, is left alone, and
so is an entry of a kind achslint has no catalogue of (HMI objects, cam
tables): their content cannot be told.

Why
---
The CNC reads a file as the kind of list its entry names. The names of a
list of another kind are no parameters of that kind, so none of them sets
anything there: the axis (or channel, or default values ...) the entry stands
for gets no list of its own, while the list meant for it is read where it does
not belong. What the CNC then does with each line is not documented, hence a
warning. The file's own lint reads it as the kind its entry names and tells
each of its names as a parameter of the other kind (LIS101).

Example
-------
```
# file: hochlauf.lis
kanal_anzahl      1
zahl_mds          1
achs_mds[0]       ./sda_mds1.lis      ( swapped with sda_mds[0]
sda_mds[0]        ./achsmds1.lis
```

```
# file: achsmds1.lis
kopf.achs_nr          1
kopf.log_achs_name    X
kenngr.achs_typ       1
```

```
# file: sda_mds1.lis
gruppe[0].achs_anzahl             1
gruppe[0].achse[0].bezeichnung    X
gruppe[0].achse[0].log_achs_nr    1
```

Use instead
-----------
Each entry names a list of its own kind; the two lists stay as they are:

```
# file: hochlauf.lis
kanal_anzahl      1
zahl_mds          1
achs_mds[0]       ./achsmds1.lis
sda_mds[0]        ./sda_mds1.lis
```

Reference
---------
P-STUP-00015 (achs_mds[i]: the axis list), P-STUP-00035 (default_achs_mds),
P-STUP-00009 (sda_mds[i]: the channel list), P-STUP-00034 (default_sda_mds),
P-STUP-00010 / P-STUP-00011 / P-STUP-00012 (tool data, zero offsets, clamp
position offsets per channel), P-STUP-00013 (hand_mds), P-STUP-00017
(achs_kw[i]), P-STUP-00146, P-STUP-00135, P-STUP-00136, P-STUP-00137,
P-STUP-00101 (external variables, real-time and hardware configuration, scene
and volumetric compensation lists); the counts P-STUP-00014, P-STUP-00016,
P-STUP-00001. The manuals name no CNC error for a list of the wrong kind.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from ..catalogue.kinds import ENTRY_KINDS, Kind, content_kind, entry_kind
from ..core.decode import UnreadableInput
from ..core.diagnostics import Diagnostic, Related, Severity
from ..core.files import same_file
from ..machine.startup import at_entry, entry_index
from ..syntax.parser import parse_bytes

if TYPE_CHECKING:
    from ..machine.resolved import Machine
    from ..machine.startup import StartupEntry

CODE = "LIS523"
NAME = "entry-names-list-of-other-kind"
FIX = "none"
SUMMARY = (
    "Start-up list entry names a list whose content is of another kind (a channel list as an axis list ...)"
)


def check_machine(machine: Machine) -> Iterator[Diagnostic]:
    for startup in machine.startups:
        defaults = [entry for entry in (startup.default, startup.default_channel) if entry is not None]
        loaded = [
            *defaults,
            *startup.loaded_axes(),
            *startup.loaded_channels(),
            *startup.loaded_compensations(),
            *startup.loaded_others(),
        ]
        for entry in sorted(loaded, key=lambda entry: entry.line):
            named = entry_kind(entry.key)
            if named is None or not named.has_catalogue:
                continue  # no catalogue (HMI objects, cam tables): what their content looks like is not known
            if entry.path is None or same_file(entry.path, startup.path):
                continue  # missing, refused or the start-up list itself: LIS504
            shown = _content(machine, entry, named)
            if shown is None or shown.prefix == named.prefix:
                continue  # unclear, or the kind named (a default list reads like the list it lies under)
            yield at_entry(
                CODE,
                startup.path,
                entry,
                Severity.WARNING,
                _message(entry, named, shown),
                (Related(str(entry.path), 1, 1, None, f"the {shown.name}"),),
            )


def _content(machine: Machine, entry: StartupEntry, named: Kind) -> Kind | None:
    """The kind the named file's content clearly shows, read as the machine reads it; None when it cannot be
    read (LIS504 or the list's own lint says why) or its content is unclear."""
    loaded = machine.load(entry, named.name)
    if loaded.data is None:
        return None
    try:
        file = parse_bytes(loaded.data, str(entry.path))
    except UnreadableInput:
        return None
    return content_kind(file)


def _message(entry: StartupEntry, named: Kind, shown: Kind) -> str:
    elsewhere = [f"`{key}`" for key, kind in ENTRY_KINDS.items() if kind.prefix == shown.prefix]
    move = (
        f"or move the entry to {' or '.join(elsewhere)}"
        if elsewhere
        else f"the reference tables name no start-up entry for a {shown.name}"
    )
    return (
        f"`{entry.key}` names `{entry.raw}`, whose content is {shown.a_name} ({shown.prefix} parameters): "
        f"the CNC reads it as {named.a_name}, and its names are no parameters of {named.a_name}, so "
        f"{_stands_for(entry, named)} gets no {named.name} of its own; name the {named.name} here, {move}"
    )


def _stands_for(entry: StartupEntry, named: Kind) -> str:
    """What the entry gives the machine, in words: `the axis this entry stands for`, `channel 2` ..."""
    if entry.key.startswith("achs_mds["):
        return "the axis this entry stands for"
    if entry.key.startswith(("sda_mds[", "werkz_data[", "nullp_data[", "pzv_data[")):
        return f"channel {entry_index(entry) + 1}"
    return "the machine"

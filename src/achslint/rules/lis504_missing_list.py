"""
What
----
A start-up list entry (`achs_mds[i]`, `default_achs_mds`, `sda_mds[i]` or
`default_sda_mds`) that names an axis or channel list which does not exist.
Relative names are resolved the way the CNC resolves them: against its working
directory, the CNC root. Set it with `--cnc-root DIR` or `cnc-root` in the
configuration; otherwise it is the start-up list's folder, or the folder above
`listen/` when the start-up list lies in `listen/` or one folder below it (the
SDK keeps `./listen/…` names in `listen/hochlauf.lis`). Backslashes separate
folders, and a name that differs from the file's in upper and lower case only
finds the file, as on Windows, where the CNC runs. The message names the file
looked for and the root. An entry whose file, links followed, lies outside
the CNC root is not read, nor one written as an absolute Windows name
(`C:\\TwinCAT\\…`, which achslint cannot look up): a warning says why, for a
list of any kind. An entry that names the start-up
list itself is an error too: it gives no list. So is a default list or a
channel list that exists but cannot be read as a list (UTF-16, binary, not
readable); an axis list like that is reported on the axis list itself. A list
of another kind the start-up list names (a compensation list `achs_kw[i]` up
to `zahl_kw`, tool data `werkz_data[i]`, zero offsets `nullp_data[i]`, the
real-time configuration `rtconf_lis` ...) that does not exist is a warning.
An object list entry written `default` (`hmi[0].objects default`, as ISG's SDK
start-up list has it) names the built-in objects, no file.
Only the entries the CNC loads are checked: an entry its count leaves out
(LIS516, LIS522) is never read, nor is one no count reaches (`achs_mds[32]`,
`achs_kw[32]` and above: `zahl_mds` and `zahl_kw` are at most 32; channel
entries `sda_mds[12]`, `werkz_data[12]` ... and above: `kanal_anzahl` is at
most 12), whatever the count says or when none is written.

Why
---
The CNC aborts the start-up when an axis or channel list named in the
start-up list is missing or unreadable. A missing list of another kind cannot
be loaded either; what the CNC does then is not documented, hence a warning.

Example
-------
```
# file: hochlauf.lis
zahl_mds             2
achs_mds[0]          ./achsmds1.lis
achs_mds[1]          ./achsmds3.lis      ( there is no achsmds3.lis
```

```
# file: achsmds1.lis
kopf.achs_nr         1
```

Use instead
-----------
Fix the path, add the list, or remove the entry (and lower `zahl_mds`); achsmds1.lis stays as it is:

```
# file: hochlauf.lis
zahl_mds             1
achs_mds[0]          ./achsmds1.lis
```

Reference
---------
P-STUP-00015 (achs_mds[i]), P-STUP-00035 (default_achs_mds), P-STUP-00009 (sda_mds[i]) and
P-STUP-00034 (default_sda_mds); list format facts §9.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from ..catalogue.kinds import entry_kind
from ..core.decode import unreadable
from ..core.diagnostics import Diagnostic, Severity
from ..core.files import same_file
from ..machine.startup import at_entry

if TYPE_CHECKING:
    from ..machine.resolved import Machine
    from ..machine.startup import Startup, StartupEntry

CODE = "LIS504"
NAME = "missing-list"
FIX = "none"
SUMMARY = "Start-up list names an axis or channel list that does not exist"

_KINDS = {
    "achs_mds": "an axis list",
    "default_achs_mds": "the default axis list",
    "sda_mds": "a channel list",
    "default_sda_mds": "the default channel list",
}


def check_machine(machine: Machine) -> Iterator[Diagnostic]:
    startups = machine.startups
    for startup in startups:
        defaults = [entry for entry in (startup.default, startup.default_channel) if entry is not None]
        channels = startup.loaded_channels()  # beyond kanal_anzahl: no configured channel (LIS522)
        not_linted = {id(entry) for entry in [*defaults, *channels]}  # no finding of their own
        for entry in [*defaults, *startup.loaded_axes(), *channels]:  # beyond zahl_mds: never read
            if entry.path is not None and same_file(entry.path, startup.path):
                severity, message = (
                    Severity.ERROR,
                    f"`{entry.key}` names `{entry.raw}`, which is this start-up list itself, not "
                    f"{_KINDS[entry.key.split('[')[0]]}: name the list file, or remove the entry",
                )
            elif entry.refused:
                severity, message = Severity.WARNING, _not_read(startup, entry, entry.refused)
            elif entry.path is None:
                severity, message = (
                    Severity.ERROR,
                    f"`{entry.key}` names `{entry.raw}`, which does not exist: looked for `{entry.looked}` "
                    f"(the CNC root is {startup.root_origin}); the CNC aborts the start-up when a list is missing",
                )
            elif id(entry) in not_linted and (why := unreadable(entry.path)) is not None:
                severity, message = (
                    Severity.ERROR,
                    f"`{entry.key}` names `{entry.raw}`, which cannot be read as a list: {why}; the CNC aborts "
                    "the start-up when a list is unreadable",
                )
            else:
                continue
            yield at_entry(CODE, startup.path, entry, severity, message)
        yield from _other_kinds(startup)


def _other_kinds(startup: Startup) -> Iterator[Diagnostic]:
    """The lists of other kinds a start-up list names (compensation lists up to `zahl_kw`, tool data, zero
    offsets ...) that do not exist: the CNC cannot load them; what it does then is documented for axis and
    channel lists only, hence a warning."""
    # beyond the counts, or beyond what any count reaches: never read (LIS516, LIS522)
    for entry in [*startup.loaded_compensations(), *startup.loaded_others()]:
        if entry.path is not None:
            continue  # there: its own lint checks it
        kind = entry_kind(entry.key)
        what = kind.name if kind is not None else "list"
        yield at_entry(
            CODE,
            startup.path,
            entry,
            Severity.WARNING,
            _not_read(startup, entry, entry.refused)
            if entry.refused
            else f"`{entry.key}` names the {what} `{entry.raw}`, which does not exist: looked for "
            f"`{entry.looked}` (the CNC root is {startup.root_origin}); the CNC cannot load it — correct the entry, "
            "add the list, or remove the entry",
        )


def _not_read(startup: Startup, entry: StartupEntry, why: str) -> str:
    """The warning for an entry achslint does not read (outside the CNC root, a FIFO, a Windows drive name)."""
    if "outside the CNC root" in why:
        remedy = "set --cnc-root or name the list (or its folder) on the command line to check it"
    elif "relative to the CNC root" in why:  # a Windows name: the reason says what to do
        remedy = f"the CNC root is {_root(startup)}"
    else:
        remedy = "name a regular list file there"
    return f"`{entry.key}` names `{entry.raw}`, which achslint does not read: {why}; {remedy}"


def _root(startup: Startup) -> str:
    """The CNC root the entries were resolved against, and how it was chosen: `/cnc (the folder above
    `listen/`; --cnc-root sets another)`."""
    return f"{startup.root} ({startup.root_origin})" if startup.root is not None else startup.root_origin

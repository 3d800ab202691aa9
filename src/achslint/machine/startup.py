"""Whole machines: several axis lists checked together (LIS501–LIS504).

A machine is the set of axis lists named by a start-up list (`hochlauf.lis`,
entries `achs_mds[i]`, with `default_achs_mds` applied under each of them the
way the CNC loads them), or else the axis lists of one folder. Each linted list
contributes a small summary (logical axis number, axis name, gantry settings,
with their lines); rules with a `check_machine(machine)` function compare the
summaries of one `resolved.Machine`, run by the lint engine over each machine.
"""

from __future__ import annotations

import fnmatch
import os
import re
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

from ..core.diagnostics import Diagnostic, Related, Severity
from ..core.files import MISSING, Scope, inside, not_a_list_file, read_list

if TYPE_CHECKING:
    from ..axis.resolved import ResolvedAxis

STARTUP_NAMES = ("hochlauf*.lis", "startup*.lis")

# What the machine-level rules know of one axis list (`summary`): a plain dict, so it pickles cheaply
# between worker processes. A member of a machine is (list name, summary).
Summary = dict[str, Any]
Member = tuple[str, Summary]
_ENTRY = re.compile(
    r"achs_mds\[[0-9]+\]|default_achs_mds|sda_mds\[[0-9]+\]|default_sda_mds|achs_kw\[[0-9]+\]"
)
# how many achs_mds[i] / achs_kw[i] entries and channels the CNC reads (P-STUP-00014/16, P-STUP-00001)
COUNTS = ("zahl_mds", "zahl_kw", "kanal_anzahl")
# the largest value of each count: zahl_mds and zahl_kw range 1 ... 32, kanal_anzahl 1 ... 12, so an entry at
# that index or above is never read, whatever the count says (LIS516, LIS522)
MAX_COUNT = {"zahl_mds": 32, "zahl_kw": 32, "kanal_anzahl": 12}
# the lists named per channel besides the channel list, `werkz_data[i]` with the channel's index i
CHANNEL_ENTRIES = ("werkz_data", "nullp_data", "pzv_data")


@dataclass
class StartupEntry:
    key: str
    raw: str
    line: int
    column: int
    path: Path | None  # resolved file, None when it does not exist or is not read
    refused: str | None = None  # why an existing file is not read (outside the machine's folder, a FIFO, ...)
    looked: Path | None = None  # where the file was looked for


@dataclass(frozen=True)
class StartupCount:
    """`zahl_mds` or `zahl_kw` as the start-up list writes it (the last assignment)."""

    key: str
    value: int | None  # None when the value is not a whole number
    raw: str
    line: int
    column: int


@dataclass
class Startup:
    path: Path
    default: StartupEntry | None = None
    axes: list[StartupEntry] = field(default_factory=list)
    root: Path | None = None  # the CNC working directory the entries are resolved against
    root_origin: str = ""  # how the root was chosen, in words (for LIS504)
    channels: list[StartupEntry] = field(default_factory=list)  # channel lists, sda_mds[i]
    default_channel: StartupEntry | None = None  # default_sda_mds
    compensations: list[StartupEntry] = field(default_factory=list)  # axis compensation lists, achs_kw[i]
    counts: dict[str, StartupCount] = field(default_factory=dict)  # zahl_mds, zahl_kw when written
    # the other lists it names (werkz_data[i], nullp_data[i], rtconf_lis ...; `catalogue.kinds.ENTRY_KINDS`)
    others: list[StartupEntry] = field(default_factory=list)
    # How the lists it names are read for the machine rules: the files, or what the editor has open.
    reader: Callable[[Path], bytes] = field(default=read_list, compare=False, repr=False)

    def loaded_axes(self) -> list[StartupEntry]:
        """The axis lists the CNC loads: with `zahl_mds` written (P-STUP-00014), the entries below that count
        — it ignores the others (LIS516 says so) —, else every `achs_mds[i]` up to `achs_mds[31]`."""
        return self._below("zahl_mds", self.axes)

    def loaded_channels(self) -> list[StartupEntry]:
        """The channel lists the CNC loads: with `kanal_anzahl` written (P-STUP-00001: the number of configured
        channels), those of the channels below that count — a list named for a channel beyond it belongs to
        no configured channel (LIS522 says so) —, else every `sda_mds[i]` up to `sda_mds[11]`."""
        return self._below("kanal_anzahl", self.channels)

    def loaded_compensations(self) -> list[StartupEntry]:
        """The axis compensation lists the CNC loads: with `zahl_kw` written (P-STUP-00016), the entries below
        that count (LIS516 says so of the others), else every `achs_kw[i]` up to `achs_kw[31]`."""
        return self._below("zahl_kw", self.compensations)

    def loaded_others(self) -> list[StartupEntry]:
        """The lists of other kinds the CNC loads: all of them, but the lists of a channel (tool data, zero
        offsets, clamp position offsets: their index is the channel's, P-STUP-00010 … P-STUP-00012) only for
        the channels `loaded_channels` counts."""
        per_channel = [entry for entry in self.others if entry.key.split("[")[0] in CHANNEL_ENTRIES]
        left_out = {id(entry) for entry in per_channel} - {
            id(entry) for entry in self._below("kanal_anzahl", per_channel)
        }
        return [entry for entry in self.others if id(entry) not in left_out]

    def _below(self, key: str, entries: list[StartupEntry]) -> list[StartupEntry]:
        """The entries whose index is below the count `key` when it is written as a whole number, and below the
        count's largest value in any case (`MAX_COUNT`: no count reaches `sda_mds[12]` or `achs_kw[32]`)."""
        count = self.counts.get(key)
        limit = MAX_COUNT[key] if count is None or count.value is None else min(count.value, MAX_COUNT[key])
        return [entry for entry in entries if entry_index(entry) < limit]


# The entries whose value `default` names no file: ISG's own SDK start-up list writes `hmi[0].objects default`
# and `channel[0].objects default` (the HMI's and the channel's built-in objects; real files win over the
# parameter table, which only says "name of the list file").
_BUILT_IN = ("hmi_objects", "channel_objects")


def names_no_file(key: str, value: str) -> bool:
    """Whether a start-up entry's value is the keyword `default` of an object list entry, not a file name."""
    from ..catalogue.kinds import entry_kind

    kind = entry_kind(key)
    return kind is not None and kind.id in _BUILT_IN and value.strip().lower() == "default"


def entry_index(entry: StartupEntry) -> int:
    """The index of an entry like `achs_mds[3]` (3)."""
    return int(entry.key[entry.key.index("[") + 1 : -1])


def is_startup_list(path: Path) -> bool:
    return _STARTUP_NAME.match(path.name.lower()) is not None


# STARTUP_NAMES as one pattern: discovery asks this of every file beside a linted list and one folder up.
_STARTUP_NAME = re.compile("|".join(fnmatch.translate(pattern) for pattern in STARTUP_NAMES))


def is_default_list(path: Path) -> bool:
    """A default axis list (`default_mds.lis`): loaded underneath the axes, not an axis of its own. A default
    channel list (`default_sda_mds.lis`, `default_sda.lis`) is none."""
    name = path.name.lower()
    return fnmatch.fnmatch(name, "default*mds*.lis") and "sda" not in name


def _entry_path(raw: str) -> Path:
    """An entry as a path: quotes dropped, Windows separators read as folder separators."""
    text = raw.strip().strip('"')
    if os.sep == "/":
        text = text.replace("\\", "/")
    return Path(text)


# A name only Windows can look up: a drive letter (`C:\TwinCAT\...`, `C:listen\...`) or a network share
# (`\\server\share\...`). Elsewhere it would be read as a folder `C:` below the CNC root.
_WINDOWS_ABSOLUTE = re.compile(r"[A-Za-z]:|\\\\[^\\]")


def _case_folded(target: Path, root: Path) -> Path | None:
    """The file `target` names below `root` when its name differs in case only, as Windows (where the CNC
    runs) finds it: each folder and the file looked up without regard to case, the exactly written name
    first; None when there is no such file."""
    try:
        parts = target.relative_to(root).parts
    except ValueError:
        return None
    found = root
    for part in parts:
        try:
            if (found / part).exists():
                found = found / part
                continue
            names = sorted(os.listdir(found))
        except (OSError, ValueError):  # a name too long for the file system, a NUL, a folder not readable
            return None
        same = [name for name in names if name.casefold() == part.casefold()]
        if not same:
            return None
        found = found / same[0]
    return found


LISTS_FOLDER = "listen"  # where the CNC keeps its lists, below its working directory


def default_cnc_root(startup: Path) -> Path:
    """The CNC working directory a start-up list's relative entries are written against, when nobody set
    one: the start-up list's own folder, or the folder above `listen/` when the list lies in `listen/`
    (the SDK layout, `./listen/achsmds1.lis` named from `listen/hochlauf.lis`) or one folder below it
    (the external-scheduling variant `listen/ExtSchedule/hochlauf.lis`). Never guessed from where the
    named files happen to exist: a start-up list must not choose which folders achslint reads."""
    folder = Path(os.path.abspath(startup)).parent
    for candidate in (folder, folder.parent):
        if candidate.name.lower() == LISTS_FOLDER and candidate.parent != candidate:
            return candidate.parent
    return folder


def _resolve(
    raw: str, root: Path, root_origin: str, scope: Scope | None
) -> tuple[Path | None, str | None, Path | None]:
    """(file, None, looked) for an entry achslint reads, (None, why, looked) for one it refuses, and
    (None, None, looked) when it is missing; `looked` is None for a name it cannot look up at all.

    A name that differs from the file's in upper and lower case only finds the file, as on Windows.

    The file, with every symbolic link followed, must lie under the CNC root or under a path the user
    gave: a start-up list cannot make achslint read (and show) `/proc/self/environ`, `../../secret.lis`
    or a link inside the machine folder that leads elsewhere.
    """
    if os.sep == "/" and _WINDOWS_ABSOLUTE.match(raw.strip().strip('"')):
        return (
            None,
            "it is an absolute Windows name, which achslint cannot look up on this computer; write it "
            "relative to the CNC root (`./listen/…`) to have the list checked",
            None,
        )
    target = Path(os.path.normpath(root / _entry_path(raw)))
    # Where the entry leads is checked before anything is looked up there: not even whether a file
    # outside the root exists shows in a finding.
    if not (inside(target, root) or (scope and scope.contains(target))):
        linked = target.is_relative_to(root)  # its name lies under the root, the file it leads to does not
        what = "it is a symbolic link that leads outside" if linked else "it lies outside"
        return None, f"{what} the CNC root {root} ({root_origin})", target
    problem = not_a_list_file(target)
    if problem in MISSING and (folded := _case_folded(target, root)) is not None:
        return _resolve(str(folded), root, root_origin, scope)  # checked again: where it leads, what it is
    if problem in MISSING:
        return None, None, target
    if problem is not None:
        return None, f"it is {problem}" if problem.startswith("a ") else problem, target
    return target, None, target


def read_startup(
    path: Path, scope: Scope | None = None, cnc_root: Path | None = None, root_origin: str = ""
) -> Startup:
    """The entries of a start-up list, resolved against `cnc_root` (`default_cnc_root` when None).

    Raises `OSError` / `decode.UnreadableInput` when the start-up list cannot be read.
    """
    from ..catalogue.kinds import entry_kind
    from ..syntax.numbers import parse_integer
    from ..syntax.parser import parse_bytes

    entries = []
    counts: dict[str, StartupCount] = {}
    for line in parse_bytes(read_list(path), str(path)).assignments():
        if not line.path_ok or not line.path or line.value is None:
            continue
        if _ENTRY.fullmatch(line.path) or entry_kind(line.path) is not None:
            if names_no_file(line.path, line.value):
                continue
            entries.append((line.path, line.value, line))
        elif line.path in COUNTS:
            number = parse_integer(line.value)
            count = number if isinstance(number, int) else None
            counts[line.path] = StartupCount(line.path, count, line.value, line.number, line.value_column)
    # A key written twice: the CNC takes the later value (LIS005 says so), so the later entry is the list.
    last = {key: index for index, (key, _, _) in enumerate(entries)}
    entries = [item for index, item in enumerate(entries) if last[item[0]] == index]
    if cnc_root is None:
        cnc_root = default_cnc_root(path)
        above = cnc_root != Path(os.path.abspath(path)).parent
        root_origin = f"{'the folder above `listen/`' if above else 'the start-up list folder'}; --cnc-root sets another"
    else:
        root_origin = root_origin or "as given"
    root = Path(os.path.abspath(cnc_root))
    startup = Startup(path, root=root, root_origin=root_origin, counts=counts)
    for key, value, line in entries:
        found, refused, looked = _resolve(value, root, root_origin or "as given", scope)
        entry = StartupEntry(key, value, line.number, line.value_column, found, refused, looked)
        if entry.key == "default_achs_mds":
            startup.default = entry
        elif entry.key == "default_sda_mds":
            startup.default_channel = entry
        elif entry.key.startswith("sda_mds"):
            startup.channels.append(entry)
        elif entry.key.startswith("achs_kw"):
            startup.compensations.append(entry)
        elif _ENTRY.fullmatch(entry.key):
            startup.axes.append(entry)
        else:  # tool data, zero offsets, the real-time configuration ...: `kinds.entry_kind` says which
            startup.others.append(entry)
    return startup


def summary(values: ResolvedAxis) -> Summary:
    """What the machine checks need from one axis list, resolved (small and picklable)."""

    def at(path: str) -> tuple[int, int] | None:
        setting = values.in_list(path)
        return (setting.line.number, setting.line.path_column) if setting else None

    def written(path: str) -> str | None:
        setting = values.setting(path)
        return setting.line.value if setting else None

    return {
        "achs_nr": values.get("kopf.achs_nr"),
        "achs_nr_at": at("kopf.achs_nr"),
        "name": values.get("kopf.log_achs_name"),
        "name_at": at("kopf.log_achs_name"),
        "gantry_ax_nr": values.get("kenngr.gantry_ax_nr"),
        "gantry_at": at("kenngr.gantry_ax_nr"),
        "resettable": values.get("kenngr.gantry_max_diff_resetable"),
        "retraction": values.get("kenngr.homing.torq_retraction_distance"),
        "torq": values.homing_type == "TORQ",
        "homing_type": values.homing_type,  # in force: after corrections, the drive's default when unset
        "homing_type_at": at("kenngr.homing.homing_type"),
        "axis_type": values.axis_type,
        "axis_type_written": written("kenngr.achs_typ"),  # as the list (or the default list) writes it
        "axis_type_at": at("kenngr.achs_typ"),
        "achs_mode": values.get("kenngr.achs_mode"),
        "achs_mode_at": at("kenngr.achs_mode"),
    }


def at_entry(
    code: str,
    startup: Path,
    entry: StartupEntry,
    severity: Severity,
    message: str,
    related: tuple[Related, ...] = (),
) -> Diagnostic:
    """A machine-rule finding on a start-up list entry: its value, the name of the list it names."""
    end = entry.column + len(entry.raw)
    return Diagnostic(
        str(startup), entry.line, entry.column, entry.line, end, code, severity, message, related=related
    )


def diagnostic(
    code: str,
    member: Member,
    where: str,
    message: str,
    severity: Severity,
    related: list[Related] | None = None,
) -> Diagnostic:
    """A machine-level diagnostic at a member list's line for `where` (or its first line)."""
    name, info = member
    line, column = info.get(where) or (1, 1)
    return Diagnostic(
        name, line, column, line, column + 1, code, severity, message, related=tuple(related or ())
    )


def repeated_values(
    code: str, members: list[Member], key: str, parameter: str, says: Callable[[str, str, str], str]
) -> Iterator[Diagnostic]:
    """A warning for every member that repeats a value of `key` an earlier member set (LIS501, LIS502).

    `says(value, note, first)` words it: the value, a note when the member's value is the default, and the
    list that used it first, which the finding also points at.
    """
    first: dict[object, Member] = {}
    for member in members:
        value = member[1][key]
        if value in (None, "", 0):
            continue
        if value not in first:
            first[value] = member
            continue
        earlier, where = first[value], f"{key}_at"
        line, column = earlier[1].get(where) or (1, 1)
        note = "" if member[1].get(where) else " (not written in this list, so the default applies)"
        yield diagnostic(
            code,
            member,
            where,
            says(str(value), note, earlier[0]),
            Severity.WARNING,
            [Related(earlier[0], line, column, parameter, "first use")],
        )


def gantry_pairs(members: list[Member]) -> Iterator[tuple[Member, Member | None]]:
    """Every gantry slave of a machine (a list with `kenngr.gantry_ax_nr`) with its master: the list whose
    `kopf.achs_nr` it names, or None when the machine has no such list (LIS503)."""
    by_number = {info["achs_nr"]: (name, info) for name, info in members}
    for name, info in members:
        if info["gantry_ax_nr"]:
            master = by_number.get(info["gantry_ax_nr"])
            # An axis naming its own number has no master (lists of one XML file share their name).
            yield (name, info), (master if master is not None and master[1] is not info else None)

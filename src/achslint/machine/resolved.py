"""The machine as the CNC loads it: one object that lint, explain, dry-run, diff and the editor all read.

A `Machine` is one of three things, told by what defines it:

- a start-up list (`hochlauf.lis`): the lists its entries name, each of the kind its entry says (axis lists
  `achs_mds[i]` up to `zahl_mds`, the default axis list `default_achs_mds` underneath each of them, channel
  lists `sda_mds[i]` with `default_sda_mds` underneath, compensation lists, tool data ...), resolved
  against its CNC root;
- a `[[machine]]` table of a configuration, for a repository without a start-up list;
- the axis XML exports of one folder (one TwinCAT project).

Each list is read once, when somebody first asks for it, through the start-up list's reader (the files, or
what the editor has open). What the CNC could not start with (a missing, refused or unreadable list) is
kept as a `MachineError` at the line of the entry that names it: the machine rules word it as LIS504, the
commands that need the list (explain, dry-run, diff) raise it.

`members` are the axis lists as a lint run saw them (one small summary each, see `startup.summary`): the
machine rules compare those, so that the editor's open buffers and the lists of one run count, never a
second reading of the same file. `view(channel)` gives the axes by the names one channel's programs use
(`model.ChannelView`): what the machine dry-run, LIS6xx and `explain` of a machine show.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import TypeVar

from ..axis.resolved import ResolvedAxis, resolve_bytes
from ..axis.source import read_one_list
from ..core.decode import UnreadableInput
from ..core.files import reason, same_file, shown_path
from .channel import ChannelList, read_channel_list
from .identity import numbered
from .startup import Member, Startup, StartupEntry, entry_index, read_startup

T = TypeVar("T")


class MachineError(Exception):
    """The machine cannot be used as asked: a file is missing or unreadable, a channel does not exist.
    `str()` names the file and line."""

    def __init__(self, message: str, path: Path | str | None = None, line: int | None = None):
        super().__init__(message)
        self.message = message
        self.path = None if path is None else str(path)
        self.line = line

    def __str__(self) -> str:
        if self.path is None:
            return self.message
        where = self.path if self.line is None else f"{self.path}:{self.line}"
        return f"{where}: {self.message}"


def open_startup(path: Path, cnc_root: Path | None = None) -> Startup:
    """A start-up list's entries for a command that needs the machine (`--cnc-root`: `cnc_root`); a
    `MachineError` naming the file when it cannot be read."""
    try:
        return read_startup(path, cnc_root=cnc_root)
    except OSError as exc:
        raise MachineError(f"cannot read the start-up list: {reason(exc)}", path) from None
    except UnreadableInput as exc:
        raise MachineError(str(exc), path) from None


@dataclass
class LoadedList:
    """One list a start-up list names, as read for the machine: its bytes, or why the CNC cannot load it."""

    entry: StartupEntry
    what: str  # the kind in words, for messages: "axis list", "default axis list", "channel list" ...
    data: bytes | None = None
    problem: MachineError | None = None

    def bytes(self) -> bytes:
        """The list's bytes; raises its `MachineError` when it cannot be read."""
        if self.problem is not None:
            raise self.problem
        assert self.data is not None
        return self.data


@dataclass(eq=False)
class Machine:
    """One machine: what defines it (`key`: the start-up list's path, the `[[machine]]` table's name or the
    folder), its start-up list if any, the axis lists a lint run read (`members`), and the lists the
    start-up list names, loaded on demand."""

    key: str
    startup: Startup | None = None
    members: list[Member] = field(default_factory=list)
    files: list[Path] = field(default_factory=list)  # the axis lists found for it, before anything is read
    defaults: Path | None = None  # the default axis list the start-up list loads under its axis lists
    _loaded: dict[tuple[str, int], LoadedList] = field(default_factory=dict, repr=False)
    _channels: dict[tuple[str, int], ChannelList | MachineError] = field(default_factory=dict, repr=False)
    _axes: list[tuple[LoadedList, ResolvedAxis | None]] | None = field(default=None, repr=False)
    _memo: dict[str, object] = field(default_factory=dict, repr=False)

    def memo(self, key: str, compute: Callable[[], T]) -> T:
        """What the rules read of the machine beyond its lists (the start-up list's own assignments ...),
        computed once for all of them."""
        if key not in self._memo:
            self._memo[key] = compute()
        return self._memo[key]  # type: ignore[return-value]

    @classmethod
    def of(cls, startup: Startup) -> Machine:
        """The machine a start-up list defines (its default list as its start-up list names it)."""
        default = startup.default
        defaults = None
        if default is not None and default.path is not None and not same_file(default.path, startup.path):
            defaults = default.path
        files = [
            e.path
            for e in startup.loaded_axes()
            if e.path is not None and not same_file(e.path, startup.path)
        ]
        return cls(str(startup.path), startup, files=files, defaults=defaults)

    def numbered(self) -> list[Member]:
        """The members whose `kopf.achs_nr` tells the axes apart (`identity.numbered`: not the template number
        TwinCAT exports repeat in every axis); what the gantry rules pair masters and slaves by."""
        return numbered(self.members)

    @property
    def startups(self) -> list[Startup]:
        """Its start-up list as a list (empty for a machine without one)."""
        return [self.startup] if self.startup is not None else []

    # -- the lists its start-up list names ------------------------------------------------------------------
    def load(self, entry: StartupEntry, what: str) -> LoadedList:
        """The list an entry of the start-up list names, read once (axis lists and default axis lists as the
        one list a file holds, XML included; other kinds as they are)."""
        key = (entry.key, entry.line)
        if key not in self._loaded:
            self._loaded[key] = self._read(entry, what)
        return self._loaded[key]

    def _read(self, entry: StartupEntry, what: str) -> LoadedList:
        startup = self._startup()
        if entry.refused:
            problem = (
                f"`{entry.key}` names the {what} `{entry.raw}`, which achslint does not read: {entry.refused}; "
                "give the CNC's working directory with --cnc-root"
            )
        elif entry.path is not None and same_file(entry.path, startup.path):
            problem = (
                f"`{entry.key}` names this start-up list itself (`{entry.raw}`), not the {what}: name the "
                f"{what}'s file"
            )
        elif entry.path is None:
            problem = (
                f"`{entry.key}` names the {what} `{entry.raw}`, which does not exist (looked for "
                f"`{entry.looked}`); the CNC does not start without it: correct the entry or give the CNC's "
                "working directory with --cnc-root"
            )
        else:
            try:
                if what.endswith("axis list"):
                    data = read_one_list(entry.path, str(entry.path), startup.reader)
                else:
                    data = startup.reader(entry.path)
                return LoadedList(entry, what, data)
            except OSError as exc:
                why = str(exc) if exc.errno is None else reason(exc)
                problem = f"cannot read the {what} `{entry.raw}`: {why}"
            except UnreadableInput as exc:
                problem = f"the {what} `{entry.raw}` cannot be read: {exc}"
        return LoadedList(entry, what, problem=MachineError(problem, startup.path, entry.line))

    def _startup(self) -> Startup:
        if self.startup is None:
            raise MachineError(f"{self.key}: this machine has no start-up list")
        return self.startup

    def default_list(self) -> LoadedList | None:
        """The default axis list (`default_achs_mds`), when the start-up list names one."""
        default = self._startup().default
        return self.load(default, "default axis list") if default is not None else None

    def axis_lists(self) -> list[tuple[LoadedList, ResolvedAxis | None]]:
        """The axis lists the CNC loads (`achs_mds[i]` up to `zahl_mds`), each with what the CNC runs: resolved
        over the default list (None when the list or the default list cannot be read)."""
        if self._axes is None:
            default = self.default_list()
            under = default.data if default is not None else None
            self._axes = []
            for entry in self._startup().loaded_axes():
                loaded = self.load(entry, "axis list")
                unusable = loaded.data is None or (default is not None and default.data is None)
                values = None if unusable else resolve_bytes(loaded.bytes(), _shown(entry), under)
                self._axes.append((loaded, values))
        return self._axes

    def resolved_axes(self) -> list[tuple[StartupEntry, bytes, ResolvedAxis]]:
        """Every loaded axis list resolved; raises the `MachineError` of the first that cannot be read
        (the default list first, as the CNC loads it first)."""
        default = self.default_list()
        if default is not None:
            default.bytes()
        found = []
        for loaded, values in self.axis_lists():
            data = loaded.bytes()
            assert values is not None
            found.append((loaded.entry, data, values))
        return found

    def channel(self, entry: StartupEntry, *, strict: bool = False) -> ChannelList | None:
        """The channel list an entry (`sda_mds[i]`) names, with the default channel list underneath; None when
        it (or the default channel list) cannot be read — LIS504 says why —, or its `MachineError` when
        `strict`."""
        key = (entry.key, entry.line)
        if key not in self._channels:
            self._channels[key] = self._channel(entry)
        found = self._channels[key]
        if isinstance(found, MachineError):
            if strict:
                raise found
            return None
        return found

    def _channel(self, entry: StartupEntry) -> ChannelList | MachineError:
        startup = self._startup()
        loaded = self.load(entry, "channel list")
        under = (
            self.load(startup.default_channel, "default channel list") if startup.default_channel else None
        )
        for part in (loaded, under):
            if part is not None and part.problem is not None:
                return part.problem
        assert loaded.data is not None
        try:
            return read_channel_list(
                loaded.data,
                _shown(entry),
                under.data if under is not None else None,
                _shown(under.entry) if under is not None else "",
            )
        except UnreadableInput as exc:
            return MachineError(
                f"the channel list `{entry.raw}` cannot be read: {exc}", startup.path, entry.line
            )

    def channel_lists(self) -> list[tuple[StartupEntry, ChannelList]]:
        """Every channel list the start-up list names that can be read, each file once (a file named twice
        is LIS518's), in the order of the entries."""
        found: list[tuple[StartupEntry, ChannelList]] = []
        seen: set[str] = set()
        for entry in self.startup.loaded_channels() if self.startup is not None else []:
            if entry.path is None or str(entry.path) in seen:
                continue
            seen.add(str(entry.path))
            channel = self.channel(entry)
            if channel is not None:
                found.append((entry, channel))
        return found

    def channel_entry(self, number: int) -> StartupEntry | None:
        """The entry naming channel `number`'s list (1-based; the later one when two name it); None when the
        start-up list names no channel list at all. `MachineError` when it names others only."""
        channels = self._startup().loaded_channels()
        if not channels:
            return None
        chosen = [entry for entry in channels if entry_index(entry) == number - 1]
        if not chosen:
            named = ", ".join(str(entry_index(entry) + 1) for entry in channels)
            count = self._startup().counts.get("kanal_anzahl")
            if count is not None and any(entry_index(e) == number - 1 for e in self._startup().channels):
                message = (
                    f"there is no channel {number}: `sda_mds[{number - 1}]` names a list for it, but "
                    f"`kanal_anzahl {count.value}` configures fewer channels, so the CNC does not load that list "
                    "(LIS522)"
                )
            else:
                message = (
                    f"there is no channel {number}: the start-up list names channel lists for channel {named} "
                    f"(sda_mds[{number - 1}] is channel {number})"
                )
            raise MachineError(message, self._startup().path)
        return chosen[-1]

    def channel_numbers(self) -> list[int]:
        """The channels the start-up list names a list for (1-based)."""
        return sorted({entry_index(entry) + 1 for entry in self._startup().loaded_channels()})


def _shown(entry: StartupEntry) -> str:
    """How a listed file is named in reports (`files.shown_path`), or the entry as written without one."""
    return shown_path(entry.path) if entry.path is not None else entry.raw

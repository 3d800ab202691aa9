"""A machine's axes as one channel's programs name them: `build_machine(hochlauf.lis) -> ChannelView`.

The start-up list names the axis lists (`achs_mds[i]`, each read with `default_achs_mds` underneath, as
the CNC loads them) and the channel lists (`sda_mds[i]`, with `default_sda_mds` underneath). The channel
list of the chosen channel gives the names NC programs use and their logical axis numbers; each name is
matched to the axis list whose `kopf.achs_nr` has that number. Without a channel list, each axis goes by
its `kopf.log_achs_name`. Gantry pairs come from the slaves' `kenngr.gantry_ax_nr` (P-AXIS-00070) and from
the coupled pairs of the channel list (`synchro_data.koppel_gruppe[g].paar[i]`). A static gantry slave
belongs to no channel (P-AXIS-00070): the channel list does not name it, so it is no programmable axis, but
it stays part of the machine, coupled to its master (`ChannelView.followers()`).

Anything the CNC would refuse to start with — the start-up list, an axis list or the channel list missing
or unreadable — raises `MachineError` naming the file and the line of the start-up list that names it.
What can be worked around (a channel entry without an axis list, a name given twice) is kept in
`ChannelView.notes`, in words.
"""

from __future__ import annotations

from pathlib import Path

from ..axis.resolved import ResolvedAxis
from .channel import ChannelList
from .model import ChannelView, Location, MachineAxis
from .resolved import Machine, MachineError, open_startup
from .startup import Startup, StartupEntry

__all__ = ["MachineError", "build_machine", "channel_view", "rename"]


def build_machine(startup: Path, *, cnc_root: Path | None = None, channel: int = 1) -> ChannelView:
    """The axes of the machine the start-up list describes, named as channel `channel` names them.

    Raises `MachineError` when the start-up list, an axis list it names or the channel list cannot be read.
    """
    return channel_view(Machine.of(_read_startup(startup, cnc_root)), channel)


def channel_view(machine: Machine, channel: int = 1) -> ChannelView:
    """A machine's axes as channel `channel`'s programs name them. Raises `MachineError` like `build_machine`."""
    startup = machine.startup
    assert startup is not None
    lists = machine.resolved_axes()  # the default list and every loaded axis list, or the first failure
    default = machine.default_list()
    defaults = default.data if default is not None else None
    view = ChannelView(startup=startup.path, channel=channel)
    channel_list = _channel_list(machine, channel, view)
    if channel_list is None:
        _named_by_axis_lists(view, lists, defaults)
    else:
        _named_by_channel(view, channel_list, lists, defaults)
    _gantry(view, channel_list)
    return view


def _read_startup(startup: Path, cnc_root: Path | None) -> Startup:
    """The start-up list's entries; the files they name shown relative to the working directory, like
    every other path in reports."""
    entries = open_startup(startup, cnc_root)
    for entry in [entries.default, entries.default_channel, *entries.axes, *entries.channels]:
        if entry is not None and entry.path is not None:
            entry.path = _relative(entry.path)
    return entries


def _relative(path: Path) -> Path:
    try:
        return path.relative_to(Path.cwd())
    except ValueError:
        return path


def _shown(entry: StartupEntry) -> str:
    return str(entry.path) if entry.path is not None else entry.raw


def _channel_list(machine: Machine, channel: int, view: ChannelView) -> ChannelList | None:
    """The chosen channel's list (with the default channel list underneath); None when the start-up list
    names no channel list at all."""
    entry = machine.channel_entry(channel)
    if entry is None:
        view.notes.append(
            "the start-up list names no channel list (sda_mds[i]): each axis goes by its kopf.log_achs_name"
        )
        return None
    result = machine.channel(entry, strict=True)
    assert result is not None
    view.channel_list = entry.path
    for problem in result.problems:
        view.notes.append(f"{problem.at.path}:{problem.at.line}: {problem.message}")
    return result


def _number(values: ResolvedAxis) -> int:
    number = values.get("kopf.achs_nr")
    return int(number) if isinstance(number, int) else 0


def _axis(
    name: str,
    entry: StartupEntry,
    data: bytes,
    values: ResolvedAxis,
    defaults: bytes | None,
    defined_at: Location | None,
    channel: int | None = None,
    spindle: bool = False,
) -> MachineAxis:
    return MachineAxis(
        name=name,
        logical_number=_number(values),
        list_path=entry.path,
        data=data,
        defaults=defaults,
        resolved=values,
        channel=channel,
        spindle=spindle or values.axis_type == "S",
        defined_at=defined_at,
    )


def _log_name(values: ResolvedAxis, entry: StartupEntry) -> tuple[str, Location | None]:
    """The axis list's kopf.log_achs_name (upper case) and where it is written (None: the default)."""
    name = str(values.get("kopf.log_achs_name") or "").upper()
    setting = values.setting("kopf.log_achs_name")
    if setting is None:
        return name, None
    line = setting.line
    path = (
        str(entry.path) if values.in_list("kopf.log_achs_name") else values.origin("kopf.log_achs_name").file
    )
    return name, Location(
        str(path), line.number, line.value_column, line.value_column + len(line.value or "")
    )


def _named_by_axis_lists(
    machine: ChannelView, lists: list[tuple[StartupEntry, bytes, ResolvedAxis]], defaults: bytes | None
) -> None:
    for entry, data, values in lists:
        name, at = _log_name(values, entry)
        axis = _axis(name, entry, data, values, defaults, at)
        if not name:
            machine.notes.append(f"{_shown(entry)}: kopf.log_achs_name is empty; the axis has no name")
            machine.other_axes.append(axis)
        elif name in machine.axes:
            machine.notes.append(
                f"{_shown(entry)}: kopf.log_achs_name {name} is the name of "
                f"{_shown_path(machine.axes[name].list_path)} too; only the first axis goes by it"
            )
            machine.other_axes.append(axis)
        else:
            machine.axes[name] = axis


def _shown_path(path: Path | None) -> str:
    return str(path) if path is not None else "?"


def _named_by_channel(
    machine: ChannelView,
    channel_list: ChannelList,
    lists: list[tuple[StartupEntry, bytes, ResolvedAxis]],
    defaults: bytes | None,
) -> None:
    by_number: dict[int, tuple[StartupEntry, bytes, ResolvedAxis]] = {}
    for entry, data, values in lists:
        number = _number(values)
        if number in by_number:
            machine.notes.append(
                f"{_shown(entry)}: kopf.achs_nr {number} is the number of {_shown(by_number[number][0])} too; "
                "the channel list's names go to the first of them"
            )
            continue
        by_number[number] = (entry, data, values)
    named: set[int] = set()
    renamed = {id(again): first for first, again in channel_list.other_names()}
    for item in channel_list.axes:
        where = f"{item.at.path}:{item.at.line}"
        if id(item) in renamed:
            first = renamed[id(item)]
            machine.notes.append(
                f"{where}: {item.slot} names logical axis {item.logical_number} {item.name}, which {first.slot} "
                f"already names {first.name} (LIS508); only the first name is used"
            )
            continue
        found = by_number.get(item.logical_number)
        if found is None:
            machine.notes.append(
                f"{where}: {item.slot} names {item.name} as logical axis {item.logical_number}, but no axis list "
                "of the start-up list has that kopf.achs_nr; the name is left out"
            )
            continue
        if item.name in machine.axes:
            machine.notes.append(
                f"{where}: {item.slot} names {item.name} a second time; only the first is used"
            )
            continue
        entry, data, values = found
        machine.axes[item.name] = _axis(
            item.name, entry, data, values, defaults, item.at, machine.channel, item.spindle
        )
        named.add(item.logical_number)
    for number, (entry, data, values) in by_number.items():
        if number not in named:
            name, at = _log_name(values, entry)
            machine.other_axes.append(_axis(name, entry, data, values, defaults, at))


def _gantry(machine: ChannelView, channel_list: ChannelList | None) -> None:
    """Gantry pairs by programmed name: from the slaves' kenngr.gantry_ax_nr, then the channel's pairs.

    A static gantry slave (kenngr.gantry_ax_nr, P-AXIS-00070) belongs to no channel: when the channel does
    not name it, it stays among `other_axes` and is coupled to its named master there, under its
    kopf.log_achs_name (or "slave of <master>" when that is empty or a programmed name already), so that the
    dry-run and `explain` move and home it with its master. A pair of the channel list couples axes of the
    channel only."""
    unnamed = {axis.logical_number: axis for axis in machine.other_axes}
    pairs: list[tuple[int, int, str, bool]] = []  # master, slave, where it is written, static gantry
    for axis in [*machine.axes.values(), *machine.other_axes]:
        number = axis.resolved.get("kenngr.gantry_ax_nr")
        if isinstance(number, int) and number > 0:
            where = f"{_shown_path(axis.list_path)} kenngr.gantry_ax_nr"
            pairs.append((number, axis.logical_number, where, True))
    for pair in channel_list.pairs if channel_list else []:
        pairs.append((pair.master, pair.slave, f"{pair.at.path}:{pair.at.line} {pair.slot}", False))
    for master_number, slave_number, source, static in pairs:
        master, slave = machine.by_number(master_number), machine.by_number(slave_number)
        if slave is None and static and master is not None and master_number != slave_number:
            slave = unnamed.get(slave_number)
            if slave is not None and slave.gantry_master is None:
                slave.name = _follower_name(machine, slave, master.name)
        if master is None or slave is None:
            missing = master_number if master is None else slave_number
            machine.notes.append(
                f"{source}: the coupled axis with logical number {missing} has no name in this channel; "
                "the pair is left out"
            )
            continue
        if (master.name, slave.name) in machine.gantry_pairs:
            continue
        if slave.gantry_master not in (None, master.name):
            machine.notes.append(
                f"{source}: {slave.name} is already the slave of {slave.gantry_master}; this pair is left out"
            )
            continue
        slave.gantry_master = master.name
        machine.gantry_pairs.append((master.name, slave.name))


def _follower_name(machine: ChannelView, slave: MachineAxis, master: str) -> str:
    """The name a gantry slave outside the channel goes by: its kopf.log_achs_name, unless no list writes
    one (the catalogue's default is no name), it is empty or taken by a programmed axis or another such
    slave; then "slave of <master>" (with its logical number when that is taken too)."""
    taken = set(machine.axes) | {axis.name for axis in machine.followers()}
    own = slave.name if slave.defined_at is not None else ""
    for name in (own, f"slave of {master}"):
        if name and name not in taken:
            return name
    return f"slave of {master} (axis {slave.logical_number})"


def rename(machine: ChannelView, names: dict[str, int], where: str) -> None:
    """Give axes the programmed names of a machine scenario's [names] table (logical number -> name): the
    fallback for a machine without a channel list, whose axes otherwise go by kopf.log_achs_name. Raises
    ValueError (with `where` in its message) when the machine has a channel list or lacks a number."""
    if not names:
        return
    if machine.channel_list is not None:
        raise ValueError(
            f"{where}: [names] is for machines without a channel list; this machine's channel list names "
            "its axes — remove [names]"
        )
    everyone = [*machine.axes.values(), *machine.other_axes]
    by_number = {axis.logical_number: axis for axis in everyone}
    for name, number in names.items():
        if number not in by_number:
            known = ", ".join(str(n) for n in sorted(by_number)) or "none"
            raise ValueError(
                f"{where}: [names] {name} = {number}: the machine has no axis {number} (it has {known})"
            )
    # An axis [names] leaves alone keeps its kopf.log_achs_name: a name given to another axis would take it
    # (the axis dropped out of the machine without a word), so the clash is refused.
    named = set(names.values())
    for axis in everyone:
        if axis.logical_number not in named and axis.name.upper() in names:
            number = names[axis.name.upper()]
            shown = f" ({axis.list_path})" if axis.list_path is not None else ""
            raise ValueError(
                f"{where}: [names] {axis.name.upper()} = {number}: axis {axis.logical_number}{shown} goes by "
                f"{axis.name} (its kopf.log_achs_name), which [names] gives axis {number}; give axis "
                f"{axis.logical_number} a name in [names] too"
            )
    old_to_new: dict[str, str] = {}
    # a gantry slave coupled outside the names stays there unless [names] names it
    followers = {id(axis) for axis in machine.followers()}
    for name, number in names.items():
        axis = by_number[number]
        old_to_new[axis.name] = name
        axis.name = name
        followers.discard(id(axis))
    machine.axes = {}
    machine.other_axes = []
    for axis in everyone:
        if axis.name and axis.name not in machine.axes and id(axis) not in followers:
            machine.axes[axis.name] = axis
        else:
            machine.other_axes.append(axis)
    machine.gantry_pairs = [(old_to_new.get(m, m), old_to_new.get(s, s)) for m, s in machine.gantry_pairs]
    for axis in everyone:
        if axis.gantry_master is not None:
            axis.gantry_master = old_to_new.get(axis.gantry_master, axis.gantry_master)
    machine.notes.append(
        f"{where}: axis names from [names] ({', '.join(f'{n} = {v}' for n, v in names.items())})"
    )

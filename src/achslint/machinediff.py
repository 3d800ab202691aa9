"""`achslint diff A B` of two machines: A and B are start-up lists (or folders holding one).

Each machine is read the way the CNC loads it (`machine.resolved.Machine`, with the CNC root of
`--cnc-root`, else the machine's configuration's `cnc-root`, else the default): every axis list its
`achs_mds[i]` entries name, resolved with its `default_achs_mds` underneath, and every channel list
(`sda_mds[i]`, with `default_sda_mds` underneath). Then:

- the axes of A and B are paired by their logical axis number (`kopf.achs_nr`, P-AXIS-00016) when the
  number names one axis on each side, else by their name (`kopf.log_achs_name`, P-AXIS-00297) when that
  is unique, else (a list named twice) axes with the same number and name in start-up order; an axis
  left unpaired was added or removed. Each pair says which identity paired it.
- each pair is compared with `listdiff.compare_axes`, the comparison `diff` runs on two lists: effective
  values with units, values written differently that the CNC corrects to the same effective value, and
  unknown parameters. The homing strategy each side runs at power-up (`homing.classify`) is compared too.
- each channel's names (axis group and spindles) are compared with the logical axis numbers they map to,
  and the channel's coupled pairs (`synchro_data.koppel_gruppe[g].paar[i]`).
- every other list the CNC loads (tool data `werkz_data[i]`, zero offsets `nullp_data[i]`, axis compensation
  `achs_kw[i]`, the real-time configuration `rtconf_lis` ...: `Startup.loaded_others` and
  `loaded_compensations`), paired by its start-up entry, and the start-up list's own settings: the values
  each writes before `Ende` (the last assignment of a name), numbers compared by value (`0x10` is `16`),
  anything else as written, so comments, blanks and order make no difference.

The report is plain data (`MachineDiffReport`, `achslint diff --format json`); output/diff.py renders it.
Which entry and file each axis came from is shown but is no difference: the CNC goes by the axis's number.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Literal, TypedDict

from .axis.resolved import ResolvedAxis
from .core.files import MISSING, is_folder, not_a_list_file, reason, shown_path
from .homing import classify
from .linting.discovery import is_startup
from .listdiff import Comparison, Difference, UnknownDifference, WrittenDifference, compare_axes, differ
from .machine.channel import ChannelList
from .machine.resolved import Machine, open_startup
from .machine.startup import LISTS_FOLDER, STARTUP_NAMES, Startup, entry_index

VERSION = 1
BY_NUMBER, BY_NAME, BY_ORDER = "logical axis number", "axis name", "number and name (in start-up order)"
Status = Literal["same", "changed", "added", "removed"]


class MachineDiffError(Exception):
    """What was given cannot be compared as two machines: one line naming the path and what to do."""


# -- the report ---------------------------------------------------------------------------------------


class MachineSide(TypedDict):
    startup: str
    cnc_root: str
    default_list: str | None
    default_channel_list: str | None


class AxisSide(TypedDict):
    entry: str  # the start-up entry that names the list: `achs_mds[0]`
    list: str
    logical_number: int  # kopf.achs_nr
    name: str  # kopf.log_achs_name
    homing: str  # the id of the homing strategy the CNC runs at power-up
    homing_title: str


class AxisDiff(TypedDict):
    status: Status  # added: only in B; removed: only in A
    matched_by: str | None  # BY_NUMBER or BY_NAME for an axis in both machines
    a: AxisSide | None
    b: AxisSide | None
    homing_differs: bool
    differences: list[Difference]
    written_differences: list[WrittenDifference]
    unknown_parameters: list[UnknownDifference]


class ChannelName(TypedDict):
    logical_number: int
    spindle: bool


class NameDiff(TypedDict):
    name: str  # the programmed name, upper case
    a: ChannelName | None  # None: the channel does not have the name
    b: ChannelName | None


class PairDiff(TypedDict):
    master: int  # logical axis numbers
    slave: int
    only_in: Literal["a", "b"]


class ChannelDiff(TypedDict):
    channel: int  # 1-based: sda_mds[channel - 1]
    status: Status
    a_list: str | None
    b_list: str | None
    names: list[NameDiff]  # only the names mapped differently
    pairs: list[PairDiff]  # only the coupled pairs one side lacks


class ValueChange(TypedDict):
    parameter: str  # as the list writes it (its last assignment)
    a: str | None  # None: the list does not write it
    b: str | None


class ListDiff(TypedDict):
    entry: str  # the start-up entry that names the list (`werkz_data[0]`), or `startup` for its own settings
    kind: str  # the list kind's id (`tool`, `zero`, `compensation`, ... `startup`)
    status: Status
    a_list: str | None
    b_list: str | None
    changes: list[ValueChange]  # only the values that differ


class MachineDiffReport(TypedDict):
    """What `achslint diff --format json` prints for two machines (documented in the README)."""

    version: int
    kind: Literal["machines"]
    a: MachineSide
    b: MachineSide
    differ: bool
    axes: list[AxisDiff]
    channels: list[ChannelDiff]
    lists: list[ListDiff]


# -- which start-up lists ------------------------------------------------------------------------------


def startup_in(path: Path) -> Path | None:
    """The start-up list `path` is or holds (by name, or by content when named otherwise): itself, the only
    start-up list in the folder (or, when the folder has none, in its `listen/` folder), or None for a file
    that is not one. `MachineDiffError` for a folder without exactly one."""
    if not is_folder(path):
        return path if is_startup(path) else None
    for folder in (path, path / LISTS_FOLDER):
        try:
            found = sorted(p for p in folder.iterdir() if p.is_file() and is_startup(p))
        except FileNotFoundError:
            continue
        except OSError as exc:
            raise MachineDiffError(f"{folder}: cannot read the folder: {reason(exc)}") from None
        if len(found) > 1:
            names = ", ".join(p.name for p in found)
            raise MachineDiffError(
                f"{folder} holds {len(found)} start-up lists ({names}): name the one meant"
            )
        if found:
            return found[0]
    patterns = ", ".join(STARTUP_NAMES)
    raise MachineDiffError(
        f"{path}: no start-up list ({patterns}) in the folder or its {LISTS_FOLDER}/ folder; name the start-up "
        "list of the machine, or an axis list"
    )


def machines_to_compare(a: Path, b: Path) -> tuple[Path, Path] | None:
    """The two start-up lists when A and B are machines, None when both are lists (the list diff).
    `MachineDiffError` when only one of them is a machine."""
    first, second = startup_in(a), startup_in(b)
    if first is None and second is None:
        return None
    if first is None or second is None:
        machine, other = (a, b) if first is not None else (b, a)
        problem = not_a_list_file(other)
        if problem in MISSING:
            raise MachineDiffError(f"{other}: {problem}")
        raise MachineDiffError(
            f"{machine} is a machine (a start-up list) and {other} is not: compare two start-up lists (or "
            "folders holding one), or two axis lists"
        )
    return first, second


# -- one machine ----------------------------------------------------------------------------------------


@dataclass
class _Axis:
    entry: str
    shown: str
    values: ResolvedAxis
    number: int
    name: str

    def side(self) -> AxisSide:
        strategy = classify(self.values)
        return {
            "entry": self.entry,
            "list": self.shown,
            "logical_number": self.number,
            "name": self.name,
            "homing": strategy.id,
            "homing_title": strategy.title,
        }


@dataclass
class _Machine:
    startup: Startup
    axes: list[_Axis]
    channels: dict[int, tuple[str, ChannelList]]  # channel number -> (list shown, its names and pairs)

    def side(self) -> MachineSide:
        entries = self.startup
        return {
            "startup": str(entries.path),
            "cnc_root": _shown_entry(entries.root) or "",
            "default_list": _shown_entry(entries.default.path) if entries.default else None,
            "default_channel_list": (
                _shown_entry(entries.default_channel.path) if entries.default_channel else None
            ),
        }


def _shown_entry(path: Path | None) -> str | None:
    return shown_path(path) if path is not None else None


def read_machine(startup: Path, cnc_root: Path | None) -> _Machine:
    """Every axis list and channel list of the machine, read as the CNC loads them.

    Raises `MachineError` (file and line) for anything the CNC would not start with."""
    entries = open_startup(startup, cnc_root)
    machine = Machine.of(entries)
    axes = []
    # Every loaded axis list (the entries beyond zahl_mds are never loaded, LIS516), a repeated number too.
    for entry, _, values in machine.resolved_axes():
        number = values.get("kopf.achs_nr")
        name = str(values.get("kopf.log_achs_name") or "").upper()
        shown = _shown_entry(entry.path) or entry.raw
        axes.append(_Axis(entry.key, shown, values, number if isinstance(number, int) else 0, name))
    channels: dict[int, tuple[str, ChannelList]] = {}
    for entry in entries.loaded_channels():  # the channels of kanal_anzahl; a later entry wins
        channel = machine.channel(entry, strict=True)
        assert channel is not None
        channels[entry_index(entry) + 1] = (_shown_entry(entry.path) or entry.raw, channel)
    return _Machine(entries, axes, channels)


# -- the comparison -----------------------------------------------------------------------------------


def _unique(axes: list[_Axis], key: str) -> dict[object, _Axis]:
    """The axes by `key` ("number" or "name"), only where the value is set and names one axis."""
    seen: dict[object, list[_Axis]] = {}
    for axis in axes:
        value = getattr(axis, key)
        if value not in (0, ""):
            seen.setdefault(value, []).append(axis)
    return {value: found[0] for value, found in seen.items() if len(found) == 1}


def pair_axes(a: list[_Axis], b: list[_Axis]) -> list[tuple[_Axis | None, _Axis | None, str | None]]:
    """(A's axis, B's axis, what paired them): by logical axis number, then by name among the rest, then
    axes alike in both (a list named twice) in start-up order; an axis of one side only comes with None.
    In A's entry order, then B's axes that A lacks."""
    partner: dict[int, tuple[_Axis, str]] = {}
    for key, how in (("number", BY_NUMBER), ("name", BY_NAME)):
        taken = {id(axis) for axis, _ in partner.values()}
        left = _unique([axis for axis in a if id(axis) not in partner], key)
        right = _unique([axis for axis in b if id(axis) not in taken], key)
        for value, axis in left.items():
            if value in right:
                partner[id(axis)] = (right[value], how)
    taken = {id(axis) for axis, _ in partner.values()}
    alike: dict[tuple[int, str], list[_Axis]] = {}
    for axis in b:
        if id(axis) not in taken:
            alike.setdefault((axis.number, axis.name), []).append(axis)
    for axis in a:
        waiting = alike.get((axis.number, axis.name))
        if id(axis) not in partner and waiting:
            partner[id(axis)] = (waiting.pop(0), BY_ORDER)
    paired = {id(axis) for axis, _ in partner.values()}
    rows: list[tuple[_Axis | None, _Axis | None, str | None]] = [
        (axis, *partner[id(axis)]) if id(axis) in partner else (axis, None, None) for axis in a
    ]
    rows.extend((None, axis, None) for axis in b if id(axis) not in paired)
    return rows


_NOTHING: Comparison = {"differences": [], "written_differences": [], "unknown_parameters": []}


def _axis_diff(a: _Axis | None, b: _Axis | None, how: str | None) -> AxisDiff:
    first, second = (a.side() if a else None), (b.side() if b else None)
    comparison = compare_axes(a.values, b.values) if a and b else _NOTHING
    homing = bool(first and second and first["homing"] != second["homing"])
    status: Status = "removed" if b is None else "added" if a is None else "same"
    if status == "same" and (homing or differ(comparison)):
        status = "changed"
    return {
        "status": status,
        "matched_by": how,
        "a": first,
        "b": second,
        "homing_differs": homing,
        **comparison,
    }


def _names(channel: ChannelList | None) -> dict[str, ChannelName]:
    """Each programmed name of a channel with the logical axis it maps to (the first slot naming it)."""
    names: dict[str, ChannelName] = {}
    for axis in channel.axes if channel else []:
        names.setdefault(axis.name, {"logical_number": axis.logical_number, "spindle": axis.spindle})
    return names


def _pairs(channel: ChannelList | None) -> set[tuple[int, int]]:
    return {(pair.master, pair.slave) for pair in channel.pairs} if channel else set()


def _channel_diff(
    number: int, a: tuple[str, ChannelList] | None, b: tuple[str, ChannelList] | None
) -> ChannelDiff:
    left, right = (a[1] if a else None), (b[1] if b else None)
    names_a, names_b = _names(left), _names(right)
    order = [*names_a, *(name for name in names_b if name not in names_a)]
    names: list[NameDiff] = [
        {"name": name, "a": names_a.get(name), "b": names_b.get(name)}
        for name in order
        if names_a.get(name) != names_b.get(name)
    ]
    pairs_a, pairs_b = _pairs(left), _pairs(right)
    pairs: list[PairDiff] = [
        {"master": master, "slave": slave, "only_in": "a" if (master, slave) in pairs_a else "b"}
        for master, slave in sorted(pairs_a ^ pairs_b)
    ]
    status: Status = (
        "removed" if b is None else "added" if a is None else "changed" if names or pairs else "same"
    )
    return {
        "channel": number,
        "status": status,
        "a_list": a[0] if a else None,
        "b_list": b[0] if b else None,
        "names": names,
        "pairs": pairs,
    }


def _written(
    data: bytes | None, name: str, skip: frozenset[str] = frozenset()
) -> dict[str, tuple[str, object]]:
    """What a list writes before `Ende`, by parameter name: (the value as written, what it compares as). The
    last assignment of a name counts (the CNC takes it, LIS005). Whole numbers and reals compare by value,
    anything else as written."""
    from .syntax.numbers import parse_integer, parse_real
    from .syntax.parser import HEX, INT, REAL, parse_bytes

    if data is None:
        return {}
    values: dict[str, tuple[str, object]] = {}
    for line in parse_bytes(data, name).assignments():
        if not line.path or line.value is None or line.path in skip:
            continue
        value = line.value.strip()
        key: object = value
        if line.value_kind in (INT, HEX):
            number = parse_integer(value)
            key = number if isinstance(number, int) else value
        elif line.value_kind == REAL:
            real = parse_real(value)
            key = real if isinstance(real, float) else value
        values[line.path] = (value, key)
    return values


def _read(startup: Startup, path: Path | None) -> bytes | None:
    """The bytes of a list the start-up list names, None when it is not there or cannot be read (its LIS504 /
    LIS5xx finding says why)."""
    if path is None:
        return None
    try:
        return startup.reader(path)
    except (OSError, ValueError):
        return None


def _list_diff(
    entry: str,
    kind: str,
    a: tuple[str, bytes | None] | None,
    b: tuple[str, bytes | None] | None,
    skip: frozenset[str] = frozenset(),
) -> ListDiff:
    left = _written(a[1], a[0], skip) if a else {}
    right = _written(b[1], b[0], skip) if b else {}
    changes: list[ValueChange] = [
        {
            "parameter": name,
            "a": left[name][0] if name in left else None,
            "b": right[name][0] if name in right else None,
        }
        for name in [*left, *(name for name in right if name not in left)]
        if (left.get(name) or (None, None))[1] != (right.get(name) or (None, None))[1]
    ]
    status: Status = "removed" if b is None else "added" if a is None else "changed" if changes else "same"
    return {
        "entry": entry,
        "kind": kind,
        "status": status,
        "a_list": a[0] if a else None,
        "b_list": b[0] if b else None,
        "changes": changes,
    }


def _other_lists(startup: Startup) -> dict[str, tuple[str, str, bytes | None]]:
    """The lists of other kinds the CNC loads, by start-up entry: (kind id, the list as shown, its bytes)."""
    from .catalogue.kinds import entry_kind

    found: dict[str, tuple[str, str, bytes | None]] = {}
    for entry in [*startup.loaded_compensations(), *startup.loaded_others()]:
        kind = entry_kind(entry.key)
        shown = _shown_entry(entry.path) or entry.raw
        found[entry.key] = (kind.id if kind is not None else "", shown, _read(startup, entry.path))
    return found


def _lists(first: Startup, second: Startup) -> list[ListDiff]:
    """The start-up lists' own settings (not their entries), then every other list either machine loads."""
    from .catalogue.kinds import STARTUP

    entries = frozenset(
        entry.key
        for startup in (first, second)
        for entry in [
            *startup.axes,
            *startup.channels,
            *startup.compensations,
            *startup.others,
            *(e for e in (startup.default, startup.default_channel) if e is not None),
        ]
    )
    rows = [
        _list_diff(
            "startup",
            STARTUP.id,
            (str(first.path), _read(first, first.path)),
            (str(second.path), _read(second, second.path)),
            entries,
        )
    ]
    left, right = _other_lists(first), _other_lists(second)
    for key in [*left, *(key for key in right if key not in left)]:
        a, b = left.get(key), right.get(key)
        kind = (a or b or ("", "", None))[0]
        rows.append(_list_diff(key, kind, (a[1], a[2]) if a else None, (b[1], b[2]) if b else None))
    return rows


def _configured_root(startup: Path) -> Path | None:
    """The `cnc-root` of the configuration that applies to a start-up list (None: not set)."""
    from .linting.config import ConfigError, discover

    try:
        return discover(startup).cnc_root()
    except ConfigError as exc:
        raise MachineDiffError(str(exc)) from None


def diff_machines(
    a: Path, b: Path, a_root: Path | None = None, b_root: Path | None = None
) -> MachineDiffReport:
    """How the machines of two start-up lists differ. `a_root`, `b_root`: their CNC roots (`--cnc-root`);
    None takes the `cnc-root` of the machine's configuration, else the default root. Raises `MachineError`
    when either machine cannot be read, `MachineDiffError` when its configuration cannot be read."""
    first = read_machine(a, a_root or _configured_root(a))
    second = read_machine(b, b_root or _configured_root(b))
    axes = [_axis_diff(left, right, how) for left, right, how in pair_axes(first.axes, second.axes)]
    channels = [
        _channel_diff(number, first.channels.get(number), second.channels.get(number))
        for number in sorted(set(first.channels) | set(second.channels))
    ]
    lists = _lists(first.startup, second.startup)
    return {
        "version": VERSION,
        "kind": "machines",
        "a": first.side(),
        "b": second.side(),
        "differ": any(row["status"] != "same" for row in [*axes, *channels, *lists]),
        "axes": axes,
        "channels": channels,
        "lists": lists,
    }

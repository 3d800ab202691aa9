"""Channel lists (`sda_mds1.lis`): the names NC programs use for the axes, and coupled pairs.

A channel list is written in the same grammar as an axis list, so it is parsed by `syntax.parse_bytes`.
Only the few channel parameters a machine needs are read (`catalogue/data/channel_parameters.json`): the axis
names and logical numbers of the axis group and of the spindles, and the coupled pairs of
`synchro_data`. Every other channel parameter is passed over without a word; a value of a read parameter
that is not usable (a name too long, a number out of range) is recorded as a `ChannelProblem` and the
entry is left out. A default channel list (`default_sda_mds`) is read underneath, the later assignment
winning, as for axis lists.
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path

from ..catalogue import fill_indices
from ..syntax import parser as syntax
from ..syntax.numbers import parse_hex, parse_int
from .model import Location


@dataclass(frozen=True)
class ChannelParameter:
    id: str
    path: str  # with `[i]` for each index
    type: str  # "STRING" or "UNS16"
    description: str = ""
    max_length: int | None = None
    min: int | None = None
    max: int | None = None
    default: int | None = None


@lru_cache(maxsize=1)
def channel_parameters() -> dict[str, ChannelParameter]:
    """The channel parameters achslint reads, by path pattern (`gruppe[i].achse[i].bezeichnung`)."""
    text = (Path(__file__).resolve().parents[1] / "catalogue" / "data" / "channel_parameters.json").read_text(
        encoding="utf-8"
    )
    return {entry["path"]: ChannelParameter(**entry) for entry in json.loads(text)["parameters"]}


@dataclass(frozen=True)
class ChannelValue:
    """One usable assignment of a read channel parameter."""

    parameter: ChannelParameter
    indices: tuple[int, ...]
    value: int | str
    at: Location  # the value's position


@dataclass(frozen=True)
class ChannelProblem:
    at: Location
    message: str


@dataclass(frozen=True)
class ChannelAxis:
    """An axis (or spindle) of the channel under its programmed name."""

    name: str  # upper case
    logical_number: int
    spindle: bool
    slot: str  # where the channel list defines it: `gruppe[0].achse[1]`, `spindel[0]`
    at: Location  # where the name is written (the number's line when the name is missing)


@dataclass(frozen=True)
class CoupledPair:
    master: int  # logical axis numbers
    slave: int
    spindles: bool  # mode 1: a pair of spindles
    slot: str  # `synchro_data.koppel_gruppe[0].paar[0]`
    at: Location


@dataclass
class ChannelList:
    name: str
    axes: list[ChannelAxis] = field(default_factory=list)
    pairs: list[CoupledPair] = field(default_factory=list)
    problems: list[ChannelProblem] = field(default_factory=list)
    _refused: set[str] = field(default_factory=set)  # slots with an unusable value (reported once)

    def other_names(self) -> list[tuple[ChannelAxis, ChannelAxis]]:
        """(first, again) for each slot that gives a logical axis another name than an earlier slot of the
        same kind gave it: two slots of the axis groups, or two spindles. (A spindle and an axis of a group
        with one number are left to LIS513: the axis list is a spindle or it is not, so one slot is wrong.)"""
        first: dict[tuple[bool, int], ChannelAxis] = {}
        found = []
        for axis in self.axes:
            earlier = first.setdefault((axis.spindle, axis.logical_number), axis)
            if earlier.name != axis.name:
                found.append((earlier, axis))
        return found


def _typed(parameter: ChannelParameter, line: syntax.Line) -> int | str | tuple[str]:
    """The value of an assignment, or a one-element tuple with what is wrong with it."""
    text = line.value or ""
    if parameter.type == "STRING":
        if line.value_kind == syntax.STRING:
            text = text[1:-1]
        elif line.value_kind not in (syntax.SYMBOL, syntax.INT):
            return (f"`{text}` is not a name",)
        if not text:
            return ("the name is empty",)
        if parameter.max_length is not None and len(text) > parameter.max_length:
            return (f"`{text}` is longer than {parameter.max_length} characters",)
        return text
    number = parse_int(text) if line.value_kind == syntax.INT else None
    if line.value_kind == syntax.HEX:
        number = parse_hex(text)
    if not isinstance(number, int):
        return (f"`{text}` is not a whole number",)
    if number == parameter.default:
        return number
    low = parameter.min if parameter.min is not None else 0
    high = parameter.max if parameter.max is not None else 65535
    if not low <= number <= high:
        return (f"{number} is outside {low} … {high}",)
    return number


def _values(data: bytes, name: str, result: ChannelList) -> dict[str, ChannelValue]:
    """The usable values of the read parameters by concrete path (the later assignment wins)."""
    known = channel_parameters()
    values: dict[str, ChannelValue] = {}
    for line in syntax.parse_bytes(data, name).assignments():
        if not line.path_ok or line.path is None:
            continue
        pattern, indices = syntax.path_pattern(line.path)
        parameter = known.get(pattern)
        if parameter is None:
            continue  # a channel parameter achslint does not read
        at = Location(name, line.number, line.value_column, line.value_column + len(line.value or ""))
        typed = _typed(parameter, line)
        if isinstance(typed, tuple):
            why = typed[0]
            result.problems.append(
                ChannelProblem(at, f"{line.path} ({parameter.id}): {why}; this entry is left out")
            )
            result._refused.add(line.path.rsplit(".", 1)[0])
            values.pop(line.path, None)
            continue
        values[line.path] = ChannelValue(parameter, indices, typed, at)
    return values


def read_channel_list(
    data: bytes, name: str, defaults: bytes | None = None, default_name: str = ""
) -> ChannelList:
    """The axes, spindles and coupled pairs of a channel list (with a default channel list underneath).

    Raises `decode.UnreadableInput` when the bytes are not a text list (UTF-16, binary).
    """
    result = ChannelList(name)
    values: dict[str, ChannelValue] = {}
    if defaults is not None:
        values.update(_values(defaults, default_name or "default channel list", result))
    values.update(_values(data, name, result))
    slots: dict[tuple[str, tuple[int, ...]], dict[str, ChannelValue]] = {}
    for value in values.values():
        group, member = value.parameter.path.rsplit(".", 1)
        slots.setdefault((group, value.indices), {})[member] = value
    for (group, indices), members in sorted(slots.items(), key=lambda item: (item[0][0], item[0][1])):
        slot = fill_indices(group, indices)
        if group.startswith("synchro_data"):
            _pair(result, slot, members)
        else:
            _axis(result, slot, members, spindle=group == "spindel[i]")
    return result


def _axis(result: ChannelList, slot: str, members: dict[str, ChannelValue], spindle: bool) -> None:
    name, number = members.get("bezeichnung"), members.get("log_achs_nr")
    if name is None or number is None:
        given = name or number
        if given is None or slot in result._refused:
            return
        missing = "log_achs_nr" if number is None else "bezeichnung"
        result.problems.append(
            ChannelProblem(given.at, f"{slot} has no {missing}, so it names no axis; this entry is left out")
        )
        return
    if number.value == 0:
        return  # an unused slot of the axis group
    result.axes.append(ChannelAxis(str(name.value).upper(), int(number.value), spindle, slot, name.at))


def _pair(result: ChannelList, slot: str, members: dict[str, ChannelValue]) -> None:
    master, slave = members.get("log_achs_nr_master"), members.get("log_achs_nr_slave")
    if master is None or slave is None or not master.value or not slave.value:
        return  # no pair in this slot (0 is the default: not used)
    mode = members.get("mode")
    result.pairs.append(
        CoupledPair(int(master.value), int(slave.value), bool(mode and mode.value == 1), slot, master.at)
    )

"""`achslint explain`: what an axis list configures for homing, and parameter cards.

`explain_list` returns plain data (output/explain.py renders it as text or JSON): the
homing strategy with its phases in words, and every homing parameter with its
value, where it came from, its unit and human unit, and whether it takes effect
under the strategy, with the reason.

`find_parameters` looks a parameter up in the catalogue of any list kind (`catalogue.kinds`) and
`parameter_card` describes it; the editor's hover shows the same card.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from functools import cache
from pathlib import Path
from typing import TYPE_CHECKING, TypedDict

from .axis.resolved import CorrectionData, plain, resolve_bytes
from .catalogue import (
    AXIS_TYPE_CODES,
    AXIS_TYPE_NAMES,
    BOOL,
    INTEGER,
    REAL,
    SYMBOL,
    Parameter,
    Scalar,
    Value,
    catalogue,
)
from .catalogue.kinds import AXIS, AXIS_PREFIX, BY_PREFIX, CONTENT_KINDS, Kind
from .catalogue.units import describe, to_human, unit_label
from .homing import HOMING_PARAMETERS, classify, effect, homing_parameter_paths, strategies_reading
from .rules import registry

if TYPE_CHECKING:
    from .axis.resolved import ResolvedAxis
    from .homing import HomingStrategy

# The JSON documents of `achslint explain --format json` (a list, or a parameter card).


class AxisInfo(TypedDict):
    name: Value | None
    number: Value | None
    axis_type: str
    drive_type: int
    drive: str
    drive_type_set: bool
    homing_type: str
    homing_type_set: bool


class AccelerationInfo(TypedDict):
    value: float
    source: str


class StrategyInfo(TypedDict):
    id: str
    title: str
    description: str
    controlled_by: str
    manual_type: str | None
    variants: list[str]
    ends_with_braking: bool
    acceleration: AccelerationInfo | None


class PhaseInfo(TypedDict):
    number: int
    name: str
    direction: str | None
    velocity_parameter: str | None
    velocity: float | None
    velocity_human: str | None
    ends_when: str
    note: str
    text: str


class CommandedInfo(TypedDict):
    """What a G74 that names the axis runs (the same strategy as at power-up except on an absolute axis)."""

    id: str
    title: str
    description: str
    phases: list[PhaseInfo]


class SourceInfo(TypedDict):
    kind: str
    line: int | None


class ParameterRow(TypedDict):
    parameter: str
    p_axis: str
    value: int | float | str | None
    written: int | float | str | None
    correction: str | None
    unit: str | None
    human: str | None
    source: SourceInfo
    effective: bool
    reason: str


class ListReport(TypedDict):
    version: int
    file: str
    gear: int
    axis: AxisInfo
    strategy: StrategyInfo
    phases: list[PhaseInfo]
    commanded: CommandedInfo
    corrections: list[CorrectionData]
    parameters: list[ParameterRow]
    loaded_under: str | None  # the default axis list the machine loads underneath, in words (None: none)


class AliasInfo(TypedDict):
    path: str
    kind: str


class _Bounds(TypedDict):
    min: float | None  # None: no lower bound is checked (a REAL64 range that states none)
    max: float | None  # None: no upper bound is checked


class RangeInfo(_Bounds, total=False):
    min_exclusive: bool  # present (True) when `min` itself is refused: "0 < x" of a REAL64


def range_words(info: RangeInfo) -> str:
    """A checked range for people: `0 .. 65535`, `above 0`, `at most 2147483647`, `above 0, at most 250`."""
    low, high = info["min"], info["max"]
    exclusive = info.get("min_exclusive", False)
    if low is not None and high is not None and not exclusive:
        return f"{low} .. {high}"
    words = []
    if low is not None:
        words.append(f"{'above' if exclusive else 'at least'} {low}")
    if high is not None:
        words.append(f"at most {high}")
    return ", ".join(words)


def outside_range(info: RangeInfo, value: object) -> bool:
    """Whether a number lies outside a checked range (the card names a default that LIS202 accepts there)."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return False
    low, high = info["min"], info["max"]
    below = low is not None and (value <= low if info.get("min_exclusive", False) else value < low)
    return below or (high is not None and value > high)


def checked_range(parameter: Parameter) -> RangeInfo | None:
    """The bounds the range check (LIS202) applies to a parameter, None when it applies none."""
    low, high = parameter.limits
    if low is None and high is None:
        return None
    if parameter.kind in (BOOL, INTEGER):  # "0 ... 1E+7" of an UNS32 is read as a float: show 10000000
        low, high = (_whole(bound) for bound in (low, high))
    info: RangeInfo = {"min": low, "max": high}
    if parameter.strict_positive_real and parameter.default != 0:
        # LIS202 refuses every number up to 0 ("must be greater than 0") except the default itself (-1 for
        # "not set" and the like).
        info["min"] = 0
        info["min_exclusive"] = True
    return info


def _whole(bound: float | None) -> float | None:
    return int(bound) if isinstance(bound, float) and bound.is_integer() else bound


class StrategyUse(TypedDict):
    id: str
    title: str
    example: str


class ParameterCard(TypedDict):
    p_axis: str  # the parameter's id (P-AXIS-00218, or P-CHAN-00036 & co. for a parameter of another kind)
    kind: str  # the kind of list it belongs to (`catalogue.kinds` id: axis, channel, startup ...)
    list: str  # that kind for people: "axis list", "channel list" ...
    path: str
    aliases: list[AliasInfo]
    type: str
    range: str | None
    checked_range: RangeInfo | None
    accepted_values: list[int] | None
    symbols: list[str] | None
    max_length: int | None
    default: Scalar
    units: dict[str, str] | None
    index_bounds: list[list[int]] | None
    drive_types: list[str] | None
    axis_types: list[str] | None
    restart_required: bool
    description: str
    manual_title: str | None
    manual: str | None
    strategies: list[StrategyUse] | None
    rules: list[str]
    errors: list[str] | None  # the CNC messages (P-ERR ids) the parameter's page and diagnosis name


def _speed_words(value: float | None, axis_type: str) -> str:
    if value is None:
        return ""
    unit = "um/s" if axis_type == "T" else "0.001deg/s"
    return describe(value, unit)


def phase_infos(strategy: HomingStrategy) -> list[PhaseInfo]:
    """The strategy's phases in words, numbered, with their speeds in list and human units."""
    axis_type = strategy.setup.axis_type
    unit = "um/s" if axis_type == "T" else "0.001deg/s"
    phases: list[PhaseInfo] = []
    for number, phase in enumerate(strategy.phases, 1):
        speed = _speed_words(phase.velocity, axis_type)
        where = phase.velocity_parameter or ""
        if phase.velocity == 0:
            text = f"{number}. {phase.name}: no move, {where} is 0" + (
                f" — {phase.note}" if phase.note else ""
            )
        else:
            text = (
                f"{number}. {phase.name}: move {phase.direction} at {speed} ({where}) until {phase.ends_when}"
            )
            if phase.note:
                text += f" — {phase.note}"
        phases.append(
            {
                "number": number,
                "name": phase.name,
                "direction": phase.direction,
                "velocity_parameter": phase.velocity_parameter,
                "velocity": phase.velocity,
                "velocity_human": to_human(phase.velocity, unit) if phase.velocity else None,
                "ends_when": phase.ends_when,
                "note": phase.note,
                "text": text,
            }
        )
    return phases


def explain_list(
    data: bytes, name: str, gear: int = 0, defaults: bytes | None = None, under: str | None = None
) -> ListReport:
    """Everything `explain FILE` shows, as JSON-ready data: the strategy the CNC runs after its corrections, at
    power-up (`strategy`, `phases`) and when a G74 names the axis (`commanded`). `defaults`: the default axis
    list loaded underneath, `under` says which (and from which start-up list) in words."""
    values = resolve_bytes(data, name, defaults)
    strategy = classify(values, gear)
    commanded = classify(values, gear, commanded=True)
    axis_type = values.axis_type
    phases = phase_infos(strategy)
    parameters = [parameter_row(values, strategy, path) for path in homing_parameter_paths(gear)]
    acceleration = strategy.acceleration
    return {
        "version": 1,
        "file": name,
        "gear": gear,
        "axis": {
            "name": values.get("kopf.log_achs_name"),
            "number": values.get("kopf.achs_nr"),
            "axis_type": AXIS_TYPE_NAMES[axis_type],
            "drive_type": values.drive_type,
            "drive": values.drive_name(),
            "drive_type_set": values.drive_type_known,
            "homing_type": values.homing_type,
            "homing_type_set": not values.homing_type_is_default,
        },
        "strategy": {
            "id": strategy.id,
            "title": strategy.title,
            "description": strategy.description,
            "controlled_by": strategy.controlled_by,
            "manual_type": strategy.manual_type,
            "variants": strategy.variants,
            "ends_with_braking": strategy.definition.ends_with_braking,
            "acceleration": {"value": acceleration.value, "source": acceleration.source}
            if strategy.moves and strategy.controlled_by == "cnc" and acceleration is not None
            else None,
        },
        "phases": phases,
        "commanded": {
            "id": commanded.id,
            "title": commanded.title,
            "description": commanded.description,
            "phases": phases if commanded.definition is strategy.definition else phase_infos(commanded),
        },
        "corrections": [c.as_dict() for c in values.corrections],
        "parameters": parameters,
        "loaded_under": under,
    }


def default_underneath(path: Path) -> tuple[bytes | None, str | None]:
    """The default axis list the CNC loads under an axis list (its machine's `default_achs_mds`, found as
    lint finds it), and where it comes from in words; (None, None) for a list no start-up list names. One
    that cannot be read is left out, and the words say so (lint reports it as LIS504)."""
    from .axis.source import read_one_list
    from .core.decode import UnreadableInput
    from .core.files import shown_path
    from .linting.config import ConfigError
    from .linting.discovery import Finder

    try:
        found = Finder(lenient=True).default_list_of(path)
    except (OSError, ValueError, ConfigError):
        return None, None
    if found is None:
        return None, None
    default, startup = found
    try:
        data = read_one_list(default, shown_path(default))
    except (OSError, UnreadableInput) as exc:
        return None, (
            f"the default axis list {shown_path(default)} that {shown_path(startup)} loads underneath cannot be read "
            f"({exc}); catalogue defaults are used instead"
        )
    return data, f"default axis list {shown_path(default)} underneath, as {shown_path(startup)} loads it"


def parameter_row(values: ResolvedAxis, strategy: HomingStrategy, path: str) -> ParameterRow:
    """One parameter of the axis (canonical path): value, unit, human unit, source, correction and effect."""
    parameter = values.parameter(path)
    value = values.get(path)
    unit = parameter.unit(values.axis_type)
    origin = values.origin(path)
    found = effect(strategy, values, path)
    correction = values.correction(path)
    return {
        "parameter": path,
        "p_axis": parameter.id,
        "value": plain(value),
        "written": plain(correction.written) if correction else None,
        "correction": correction.error if correction else None,
        "unit": unit_label(unit) or None,
        "human": to_human(value, unit)
        if isinstance(value, (int, float)) and not isinstance(value, bool)
        else None,
        "source": {"kind": origin.kind, "line": origin.setting.line.number if origin.setting else None},
        "effective": found.effective,
        "reason": found.reason,
    }


# --- parameter cards --------------------------------------------------------------------------


def strategies_using(parameter: Parameter) -> list[StrategyUse] | None:
    """The registered strategies that read a homing parameter (title and example); None for other parameters.
    A strategy that runs only on axis types the parameter does not apply to is left out: `explain LIST`
    marks the parameter ineffective there whatever its value (cam_direct_access under spindle homing)."""
    generic = parameter.path.replace("lr_hw[i]", "lr_hw[0]")
    if generic not in HOMING_PARAMETERS:
        return None
    return [
        {"id": d.id, "title": d.title, "example": d.example}
        for d in strategies_reading(generic)
        if not parameter.axis_types or set(parameter.axis_types) & _axis_types_of(d.id, d.example)
    ]


@cache
def _axis_types_of(strategy_id: str, example: str) -> frozenset[str]:
    """The axis types ("T", "R", "S") for which a strategy's example list, with that axis type in place of
    the one it sets, still selects the strategy: the flying spindle homings only for spindles, the cam
    homings of linear and rotary axes not for a spindle (whose ref_ohne_rev 1 makes it fly)."""
    lines = [line for line in example.splitlines() if line.split()[:1] != ["kenngr.achs_typ"]]
    found = set()
    for code, axis_type in AXIS_TYPE_CODES.items():
        text = "\n".join([*lines, f"kenngr.achs_typ {code}", "Ende", ""])
        if classify(resolve_bytes(text.encode(), "example.lis")).id == strategy_id:
            found.add(axis_type)
    return frozenset(found)


def rules_checking(parameter: Parameter, kind: Kind = AXIS) -> list[str]:
    """The rules that check a parameter in a list of `kind`: the value rules that run for that kind, and
    (in axis lists) the rules that read the parameter together with others."""
    rules = registry()
    codes: list[str] = []
    value = parameter.kind
    if value in (BOOL, INTEGER, REAL, SYMBOL):
        codes.append("LIS201")
    if value in (INTEGER, REAL):
        codes.append("LIS202")
    if value == SYMBOL or parameter.symbols:
        codes.append("LIS203")
    if parameter.max_length:
        codes.append("LIS206")
    codes = [code for code in codes if rules[code].applies_to(kind.id)]
    if kind.prefix != AXIS_PREFIX:
        return codes  # the rules' PARAMETERS are axis paths: a channel's `kopf.achs_nr` is another parameter
    if parameter.id == "P-AXIS-00015":
        codes.append("LIS204")
    for code, rule in rules.items():
        if parameter.path in rule.parameters and code not in codes:
            codes.append(code)
    return codes


@dataclass(frozen=True)
class Found:
    """A parameter and the kind of list whose catalogue holds it."""

    kind: Kind
    parameter: Parameter


_ID = re.compile(r"(P-[A-Z]{4})-?([0-9]+)", re.IGNORECASE)


def find_parameters(query: str, kind: Kind | None = None) -> list[Found]:
    """The parameters a name, alias or id stands for (`vb_reflow`, `gruppe[0].achse[0].bezeichnung`,
    `P-CHAN-00036`), in the catalogue of `kind`, or else of the kind its id prefix names, else the axis
    catalogue's parameter (as `explain` always answered), else the one of every other kind that knows the
    name; several when kinds other than the axis kind share it. Empty: no catalogue knows it."""
    text = query.strip()
    match = _ID.fullmatch(text)
    if match and match.group(1).upper() != AXIS_PREFIX:
        owner = BY_PREFIX.get(match.group(1).upper())
        if owner is None or (kind is not None and kind.table != owner.table):
            return []
        cat = owner.catalogue()
        found = cat.by_id.get(f"{owner.prefix}-{int(match.group(2)):05d}") if cat is not None else None
        return [Found(kind or owner, found)] if found is not None else []
    if kind is not None:
        cat = kind.catalogue()
        found = cat.find(text) if cat is not None else None
        return [Found(kind, found)] if found is not None else []
    found = catalogue().find(text)
    if found is not None or match:
        return [Found(AXIS, found)] if found is not None else []
    hits = []
    for other in CONTENT_KINDS:
        cat = other.catalogue() if other.prefix != AXIS_PREFIX else None
        found = cat.find(text) if cat is not None else None
        if found is not None:
            hits.append(Found(other, found))
    return hits


def parameter_card(parameter: Parameter, kind: Kind = AXIS) -> ParameterCard:
    """A parameter's card: what the catalogue of its kind says, and (in axis lists) the drive and axis
    types it applies to and the homing strategies that read it."""
    axis = kind.prefix == AXIS_PREFIX
    drives = catalogue().drive_type_names if axis else {}
    return {
        "p_axis": parameter.id,
        "kind": kind.id,
        "list": kind.name,
        "path": parameter.path,
        "aliases": [{"path": a.path, "kind": a.kind} for a in parameter.aliases],
        "type": parameter.type,
        "range": parameter.range_text or None,
        "checked_range": checked_range(parameter),
        "accepted_values": list(parameter.allowed) or None,
        "symbols": list(parameter.symbols) or None,
        "max_length": parameter.max_length,
        "default": plain(parameter.typed_default)
        if parameter.typed_default is not None
        else parameter.default,
        "units": {AXIS_TYPE_NAMES[k]: unit_label(v) for k, v in parameter.units.items() if v} or None,
        "index_bounds": [list(b) for b in parameter.index_bounds] or None,
        "drive_types": [f"{code} {drives.get(code, '')}".strip() for code in parameter.drive_types] or None,
        "axis_types": [AXIS_TYPE_NAMES[a] for a in parameter.axis_types] or None,
        "restart_required": parameter.restart,
        "description": parameter.summary,
        "manual_title": parameter.title or None,
        "manual": parameter.source or None,
        "strategies": strategies_using(parameter) if axis else None,
        "rules": rules_checking(parameter, kind),
        "errors": list(parameter.errors) or None,
    }

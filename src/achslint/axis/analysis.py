"""Syntax tree + catalogue -> typed settings.

For every assignment the CNC would read, this stage finds the catalogue entry
(by canonical name or alias), converts the written value to the parameter's
type and records what it could not convert as a fact (`facts.py`). Rule
modules turn those facts into findings; no rule parses values itself, and this
module holds no rule code or message text.

The catalogue is the axis catalogue or that of another list kind (a channel
list's, `catalogue.kinds`): the same entries, so the same conversion. Only an
axis list has an axis and drive type, and only the axis catalogue holds the
P-AXIS parameters a reference names: in a list of another kind a reference
is read, not resolved.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from ..catalogue import (
    AXIS_TYPE_CODES,
    BOOL,
    INTEGER,
    REAL,
    STRING,
    SYMBOL,
    Catalogue,
    Parameter,
    Resolution,
    Value,
    catalogue,
)
from ..core.pause import pause
from ..syntax import parser as syntax
from ..syntax.numbers import NumberProblem, Reference, parse_hex, parse_int, parse_real, parse_reference
from .facts import (
    BadReference,
    CommentReadAsValue,
    IndexOutOfBounds,
    MissingValue,
    NotAccepted,
    NotBoolean,
    NotPositive,
    OutOfRange,
    RealForInteger,
    TextAfterString,
    TextForNumber,
    TooLong,
    UnknownSymbol,
    UnusableNumber,
    ValueFact,
)

__all__ = ["Analysis", "Reference", "Setting", "analyse", "combined_flags", "comment_in_value_position"]


@dataclass(slots=True, eq=False)
class Setting:
    """One assignment as the CNC reads it."""

    line: syntax.Line
    resolution: Resolution | None
    value: Value | Reference | None = None  # the converted value; None when it could not be converted
    problems: tuple[ValueFact, ...] = ()  # a tuple: most settings have none and share the empty one
    misspelt: bool = field(init=False)
    canonical: str | None = field(init=False)  # canonical concrete path; None when unknown

    def __post_init__(self) -> None:
        resolution = self.resolution
        if resolution is None:
            self.misspelt, self.canonical = False, None
        else:
            self.misspelt = resolution.misspelt
            self.canonical = None if resolution.misspelt else resolution.canonical

    @property
    def parameter(self) -> Parameter | None:
        return self.resolution.parameter if self.resolution else None

    @property
    def known(self) -> bool:
        return self.canonical is not None

    @property
    def written_value(self) -> str:
        return self.line.value or ""

    @property
    def comparable(self) -> Value | Reference:
        """What two assignments are compared by: the typed value, else the written text."""
        if self.value is not None and not self.problems:
            return self.value
        return (self.line.value or "").strip('"')

    @property
    def spelling(self) -> str:
        """ "canonical" or the alias kind this assignment is written with."""
        alias = self.resolution.alias if self.resolution else None
        return alias.kind if alias else "canonical"

    def add_problem(self, problem: ValueFact) -> None:
        self.problems = (*self.problems, problem)


@dataclass(slots=True)
class Analysis:
    file: syntax.ListFile
    settings: list[Setting]
    axis_type: str = "T"
    axis_type_known: bool = False
    drive_type: int | None = None
    _groups: dict[str, list[Setting]] | None = None

    def by_canonical(self) -> dict[str, list[Setting]]:
        """Known assignments grouped by canonical path (computed once)."""
        if self._groups is None:
            self._groups = {}
            for setting in self.settings:
                if setting.canonical is not None:
                    self._groups.setdefault(setting.canonical, []).append(setting)
        return self._groups


_COMMENT_STARTS = ("#", "/*", ";")
_NO_VALUE_STARTS = (*_COMMENT_STARTS, "(")  # what a comment in the place of the value begins with
_ARRAY_NAME = re.compile(r"(\w+)\[i\]")
_WRITTEN_INDEX = re.compile(r"\[[0-9]+\]")


_REAL = syntax.REAL
_NUMBERS = (syntax.INT, syntax.HEX, syntax.REAL)

PAUSE_EVERY = 512  # settings between two pause points (well under a millisecond of work)


def analyse(file: syntax.ListFile, cat: Catalogue | None = None) -> Analysis:
    cat = cat or catalogue()
    resolve = cat.resolve
    settings: list[Setting] = []
    add = settings.append
    for count, line in enumerate(file.assignments(), 1):
        path = line.path
        if line.path_ok and path is not None:  # an assignment always has a path
            add(Setting(line, resolve(path)))
        if not count % PAUSE_EVERY:
            pause()  # the language server's worker gives way to the editor here (core.pause)
    analysis = Analysis(file, settings)
    axes = _describes_axes(cat)
    if axes:
        _axis_and_drive(analysis, cat)
    for count, setting in enumerate(settings, 1):
        if not count % PAUSE_EVERY:
            pause()
        resolution = setting.resolution
        if setting.canonical is not None and resolution is not None:  # known: not by a misspelling
            if not resolution.in_bounds and resolution.alias is None:
                _check_indices(setting, resolution)
            if not setting.problems:
                _check_value(setting, resolution.parameter, analysis, cat, axes)
    return analysis


def _check_indices(setting: Setting, resolution: Resolution) -> None:
    """Array indices inside the bounds of the catalogue (aliases carry no indices of their own)."""
    if resolution.in_bounds or resolution.alias is not None:
        return
    parameter = resolution.parameter
    line = setting.line
    arrays = _ARRAY_NAME.findall(parameter.path)
    written = list(_WRITTEN_INDEX.finditer(line.path or ""))
    for position, (index, (low, high)) in enumerate(
        zip(resolution.indices, parameter.index_bounds, strict=False)
    ):
        if low <= index <= high:
            continue
        start = line.path_column + written[position].start()
        text = written[position].group(0)
        setting.add_problem(
            IndexOutOfBounds(
                arrays[position],
                None if index == syntax.HUGE else index,
                text[1:-1],
                low,
                high,
                (start, start + len(text)),
            )
        )


def _last_ints(settings: list[Setting], parameter_ids: tuple[str, ...]) -> dict[str, int]:
    """The integer each of the parameters is set to last, by id (one walk through the list for all)."""
    values: dict[str, int] = {}
    for setting in settings:
        resolution = setting.resolution
        if setting.canonical is None or resolution is None:  # unknown or misspelt
            continue
        parameter = resolution.parameter
        if parameter.id not in parameter_ids:
            continue
        line = setting.line
        number = _as_int(line)
        written = line.value
        if isinstance(number, int):
            values[parameter.id] = number
        elif line.value_kind == syntax.SYMBOL and written in parameter.symbol_codes:
            values[parameter.id] = parameter.symbol_codes[written]
    return values


def _describes_axes(cat: Catalogue) -> bool:
    """Whether the catalogue is the axis catalogue (it has the axis and drive type, P-AXIS-00018/20)."""
    return "P-AXIS-00020" in cat.by_id


def _axis_and_drive(analysis: Analysis, cat: Catalogue) -> None:
    last = _last_ints(analysis.settings, ("P-AXIS-00018", "P-AXIS-00020"))
    axis_code = last.get("P-AXIS-00018")
    if axis_code in AXIS_TYPE_CODES:
        analysis.axis_type = AXIS_TYPE_CODES[axis_code]
        analysis.axis_type_known = True
    drive = last.get("P-AXIS-00020")
    # An invalid drive type is reported by the range check; nothing is inferred from it.
    analysis.drive_type = drive if drive in cat.by_id["P-AXIS-00020"].allowed else None


def _as_int(line: syntax.Line) -> int | NumberProblem | None:
    """The integer an INT or HEX value stands for (or why there is none); None for other kinds."""
    if line.value_kind == syntax.INT:
        return parse_int(line.value or "")
    if line.value_kind == syntax.HEX:
        return parse_hex(line.value or "")
    return None


def comment_in_value_position(line: syntax.Line) -> bool:
    """True when the 'value' is really the start of a comment (`name   # text`)."""
    value = line.value or ""
    return line.value_kind in (syntax.SYMBOL, syntax.BAD_STRING) and value.startswith(_NO_VALUE_STARTS)


def _check_value(
    setting: Setting, parameter: Parameter, analysis: Analysis, cat: Catalogue, axes: bool
) -> None:
    """Convert the value of a known assignment, or record why it cannot be (`axes`: the catalogue is the
    axis catalogue, `_describes_axes`)."""
    line = setting.line
    kind = parameter.kind
    value_kind = line.value_kind
    text = line.value or ""

    # A number for a number or a flag first (most assignments): none of the checks below concerns it.
    if value_kind in _NUMBERS:
        if kind == INTEGER and value_kind != _REAL:
            _check_integer(setting, parameter, text, value_kind, analysis.axis_type)
            return
        if kind == REAL:
            _check_real(setting, parameter, text, value_kind, analysis.axis_type)
            return
        if kind == BOOL:
            _check_bool(setting, parameter, text, value_kind)
            return

    add_problem = setting.add_problem
    if value_kind == syntax.BAD_STRING:
        return  # a syntax error, reported with the line
    if value_kind == syntax.REFERENCE:
        setting.value = _reference(setting, parameter, cat, analysis)
        return
    if value_kind is None or (text.startswith("(")):
        # No value at all, or a `(` comment right after the name.
        if kind in (STRING,):
            setting.value = ""
            return
        add_problem(MissingValue())
        return
    if value_kind == syntax.SYMBOL and text.startswith(_NO_VALUE_STARTS):  # comment_in_value_position
        if kind in (STRING, SYMBOL):
            add_problem(CommentReadAsValue((line.value or "") + line.sep2 + (line.rest or "")))
        else:
            add_problem(MissingValue(text))
        return

    flags = combined_flags(line) if kind == SYMBOL and not axes else None
    if flags is not None:
        _check_flags(setting, parameter, flags)
        return
    if kind == BOOL:
        _check_bool(setting, parameter, text, value_kind)
    elif kind == INTEGER:
        _check_integer(setting, parameter, text, value_kind, analysis.axis_type)
    elif kind == REAL:
        _check_real(setting, parameter, text, value_kind, analysis.axis_type)
    elif kind == SYMBOL:
        _check_symbol(setting, parameter, text, value_kind)
    else:
        string = text[1:-1] if value_kind == syntax.STRING else text
        setting.value = string
        if parameter.max_length is not None and len(string) > parameter.max_length:
            add_problem(TooLong(len(string), parameter.max_length))
    textual = value_kind in (syntax.SYMBOL, syntax.STRING)
    if kind in (STRING, SYMBOL) and textual and line.rest is not None and not line.rest.startswith("("):
        add_problem(TextAfterString(line.rest))


def _check_bool(setting: Setting, parameter: Parameter, text: str, value_kind: str) -> None:
    if value_kind in (syntax.INT, syntax.HEX):
        number = _as_int(setting.line)
        if number in (0, 1):
            setting.value = bool(number)
            return
        setting.add_problem(NotBoolean(text, replacement="1" if number else "0"))
        return
    if value_kind == syntax.SYMBOL:
        if text in ("TRUE", "FALSE"):
            setting.value = text == "TRUE"
            return
        if parameter.symbols and text in parameter.symbols:
            setting.value = parameter.symbols.index(text) == 1
            return
        if parameter.symbols:
            _unknown_symbol(setting, parameter, text)
            return
    setting.add_problem(NotBoolean(text))


def _check_integer(
    setting: Setting, parameter: Parameter, text: str, value_kind: str, axis_type: str
) -> None:
    if value_kind in (syntax.INT, syntax.HEX):
        number = parse_int(text) if value_kind == syntax.INT else parse_hex(text)
        if isinstance(number, NumberProblem):
            setting.add_problem(UnusableNumber(text, number))
            return
        setting.value = number
        _check_range(setting, parameter, number, axis_type)
        return
    if value_kind == syntax.SYMBOL and parameter.symbols:
        if text in parameter.symbols:
            setting.value = parameter.symbol_codes.get(text, text)
            return
        _unknown_symbol(setting, parameter, text)
        return
    if value_kind == syntax.REAL:
        as_float = parse_real(text)
        replacement = str(int(as_float)) if isinstance(as_float, float) and as_float.is_integer() else None
        setting.add_problem(RealForInteger(text, replacement))
        return
    setting.add_problem(TextForNumber(text))


def _check_real(setting: Setting, parameter: Parameter, text: str, value_kind: str, axis_type: str) -> None:
    if value_kind in (syntax.INT, syntax.HEX, syntax.REAL):
        number = parse_real(text)
        if isinstance(number, NumberProblem):
            setting.add_problem(UnusableNumber(text, number))
            return
        setting.value = number
        _check_range(setting, parameter, number, axis_type)
        return
    setting.add_problem(TextForNumber(text))


def _check_range(setting: Setting, parameter: Parameter, number: float, axis_type: str) -> None:
    """A number inside the parameter's accepted codes or range (`axis_type` gives the unit of a finding)."""
    if parameter.allowed:
        if number not in parameter.allowed and number != parameter.default:
            setting.add_problem(NotAccepted(number, tuple(parameter.allowed)))
        return
    if number == parameter.outside_default:
        return  # an out-of-range default that means "not set" (limits: the values between are not accepted)
    low, high = parameter.limits
    if parameter.strict_positive_real and number <= 0 and number != parameter.default:
        setting.add_problem(NotPositive(number, parameter.unit(axis_type)))
        return
    if low is not None and number < low:
        setting.add_problem(OutOfRange(number, low, None, parameter.unit(axis_type)))
    elif high is not None and number > high:
        setting.add_problem(OutOfRange(number, None, high, parameter.unit(axis_type)))


def _check_symbol(setting: Setting, parameter: Parameter, text: str, value_kind: str) -> None:
    if value_kind == syntax.STRING:
        text = text[1:-1]
    if text in parameter.symbols:
        setting.value = text
        return
    codes = parameter.symbol_codes
    if value_kind in (syntax.INT, syntax.HEX) and codes:
        number = _as_int(setting.line)
        for symbol, code in codes.items():
            if code == number:
                setting.value = symbol
                return
    _unknown_symbol(setting, parameter, text)


def combined_flags(line: syntax.Line) -> tuple[str, ...] | None:
    """The symbols of an OR-combined value (`REPORT | REPORT_EXTENDED |PRINT`), None for a single value.

    Lists other than axis lists combine flags with `|` and free spacing (the start-up list's
    `error_protocol_mode`, `...path_preparation.function`; format facts §6); a `(` starts the comment."""
    if line.value_kind != syntax.SYMBOL:
        return None
    text = ((line.value or "") + line.sep2 + (line.rest or "")).split("(", 1)[0]
    if "|" not in text:
        return None
    return tuple(part.strip() for part in text.split("|"))


def _check_flags(setting: Setting, parameter: Parameter, flags: tuple[str, ...]) -> None:
    """Every flag of an OR-combined value is one of the parameter's symbols (an empty one, as in
    `REPORT |`, makes the whole combination unknown)."""
    for flag in flags:
        if flag not in parameter.symbols:
            _unknown_symbol(setting, parameter, flag or " | ".join(flags).strip(" |") + " |")
            return
    setting.value = " | ".join(flags)


def _unknown_symbol(setting: Setting, parameter: Parameter, text: str) -> None:
    setting.add_problem(UnknownSymbol(text, tuple(parameter.symbols), tuple(parameter.symbol_codes.values())))


def _reference(
    setting: Setting, parameter: Parameter, cat: Catalogue, analysis: Analysis
) -> Reference | None:
    written = setting.line.value or ""
    reference = parse_reference(written)
    if isinstance(reference, NumberProblem):
        setting.add_problem(BadReference("unreadable", written, problem=reference))
        return None
    if not _describes_axes(cat):
        return reference  # names an axis parameter, which this kind's catalogue does not hold
    target = cat.by_id.get(reference.target)
    problem = None
    if target is None:
        problem = BadReference("unknown", written, reference)
    elif target.id == parameter.id:
        problem = BadReference("itself", written, reference)
    elif _category(target) != _category(parameter):
        problem = BadReference("kind", written, reference, target_path=target.path, target_type=target.type)
    elif parameter.unit(analysis.axis_type) != target.unit(analysis.axis_type):
        problem = BadReference(
            "unit",
            written,
            reference,
            target_path=target.path,
            own_unit=parameter.unit(analysis.axis_type),
            target_unit=target.unit(analysis.axis_type),
        )
    elif reference.index is not None and target.index_bounds:
        low, high = target.index_bounds[0]
        if not low <= reference.index <= high:
            problem = BadReference("index", written, reference, low=low, high=high)
    if problem is not None:
        setting.add_problem(problem)
        return None
    return reference


def _category(parameter: Parameter) -> str:
    return {BOOL: "bool", INTEGER: "number", REAL: "number"}.get(parameter.kind, "text")

"""Syntax tree + catalogue -> typed settings.

For every assignment the CNC would read, this stage finds the catalogue entry
(by canonical name or alias), converts the written value to the parameter's
type and records each problem with the value. Rules then report what this
stage found; no rule parses values itself.
"""

from __future__ import annotations

import difflib
import re
from dataclasses import dataclass, field

from . import syntax
from .catalogue import (
    AXIS_TYPE_CODES,
    BOOL,
    INTEGER,
    REAL,
    STRING,
    SYMBOL,
    Catalogue,
    Parameter,
    Resolution,
    catalogue,
)
from .numbers import NumberProblem, Reference, parse_hex, parse_int, parse_real, parse_reference
from .units import describe, unit_label

__all__ = ["Analysis", "Reference", "Setting", "ValueProblem", "analyse", "comment_in_value_position"]


@dataclass(slots=True)
class ValueProblem:
    code: str
    message: str
    replacement: str | None = None  # a value that would fix it, when there is a clear one
    span: object = "value"  # the part of the line at fault: "value", "rest" or (column, end_column)


@dataclass(slots=True, eq=False)
class Setting:
    """One assignment as the CNC reads it."""

    line: syntax.Line
    resolution: Resolution | None
    value: object = None
    problems: tuple[ValueProblem, ...] = ()  # a tuple: most settings have none and share the empty one
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
    def comparable(self) -> object:
        """What two assignments are compared by: the typed value, else the written text."""
        if self.value is not None and not self.problems:
            return self.value
        return (self.line.value or "").strip('"')

    @property
    def spelling(self) -> str:
        """"canonical" or the alias kind this assignment is written with."""
        alias = self.resolution.alias if self.resolution else None
        return alias.kind if alias else "canonical"

    def add_problem(self, problem: ValueProblem) -> None:
        self.problems = (*self.problems, problem)

    def problem(self, code: str) -> ValueProblem | None:
        for problem in self.problems:
            if problem.code == code:
                return problem
        return None


@dataclass(slots=True)
class Analysis:
    file: syntax.ListFile
    settings: list[Setting]
    axis_type: str = "T"
    axis_type_known: bool = False
    drive_type: int | None = None
    _groups: dict | None = None

    def by_canonical(self) -> dict[str, list[Setting]]:
        """Known assignments grouped by canonical path (computed once)."""
        if self._groups is None:
            self._groups = {}
            for setting in self.settings:
                if setting.canonical is not None:
                    self._groups.setdefault(setting.canonical, []).append(setting)
        return self._groups


_COMMENT_STARTS = ("#", "/*", ";")
_ARRAY_NAME = re.compile(r"(\w+)\[i\]")
_WRITTEN_INDEX = re.compile(r"\[[0-9]+\]")


def analyse(file: syntax.ListFile, cat: Catalogue | None = None) -> Analysis:
    cat = cat or catalogue()
    settings = [Setting(line, cat.resolve(line.path)) for line in file.assignments() if line.path_ok]
    analysis = Analysis(file, settings)
    _axis_and_drive(analysis, cat)
    for setting in settings:
        if setting.known:
            _check_indices(setting)
            if not setting.problems:
                _check_value(setting, analysis, cat)
    return analysis


def _check_indices(setting: Setting) -> None:
    """Array indices inside the bounds of the catalogue (aliases carry no indices of their own)."""
    resolution = setting.resolution
    if resolution.in_bounds or resolution.alias is not None:
        return
    parameter = resolution.parameter
    line = setting.line
    arrays = _ARRAY_NAME.findall(parameter.path)
    written = list(_WRITTEN_INDEX.finditer(line.path))
    for position, (index, (low, high)) in enumerate(zip(setting.resolution.indices, parameter.index_bounds)):
        if low <= index <= high:
            continue
        array = arrays[position]
        start = line.path_column + written[position].start()
        shown = index if index != syntax.HUGE else f"`{written[position].group(0)[1:-1]}`"
        setting.add_problem(ValueProblem(
            "LIS104",
            f"index {shown} of `{array}` in `{line.path}` is out of bounds: {parameter.id} allows "
            f"{array}[{low}]..{array}[{high}] (indices are zero-based)",
            span=(start, start + len(written[position].group(0))),
        ))


def _last_int(settings: list[Setting], parameter_id: str) -> int | None:
    value = None
    for setting in settings:
        if setting.known and setting.parameter.id == parameter_id:
            number = _as_int(setting.line)
            if isinstance(number, int):
                value = number
            elif setting.line.value_kind == syntax.SYMBOL:
                codes = setting.parameter.symbol_codes
                if setting.line.value in codes:
                    value = codes[setting.line.value]
    return value


def _axis_and_drive(analysis: Analysis, cat: Catalogue) -> None:
    axis_code = _last_int(analysis.settings, "P-AXIS-00018")
    if axis_code in AXIS_TYPE_CODES:
        analysis.axis_type = AXIS_TYPE_CODES[axis_code]
        analysis.axis_type_known = True
    drive = _last_int(analysis.settings, "P-AXIS-00020")
    # An invalid drive type is reported by the range check; nothing is inferred from it.
    analysis.drive_type = drive if drive in cat.by_id["P-AXIS-00020"].allowed else None


def _as_int(line: syntax.Line) -> int | NumberProblem | None:
    """The integer an INT or HEX value stands for (or why there is none); None for other kinds."""
    if line.value_kind == syntax.INT:
        return parse_int(line.value)
    if line.value_kind == syntax.HEX:
        return parse_hex(line.value)
    return None


def _unusable_number(setting: Setting, text: str, problem: NumberProblem) -> None:
    parameter = setting.parameter
    holds = f", far more than a {parameter.type} holds" if problem.reason == "digits" else ""
    setting.add_problem(ValueProblem(
        "LIS202", f"`{setting.canonical}` = `{text}` {problem}{holds}; {_expected(parameter)} is expected"))


def comment_in_value_position(line: syntax.Line) -> bool:
    """True when the 'value' is really the start of a comment (`name   # text`)."""
    value = line.value or ""
    return line.value_kind in (syntax.SYMBOL, syntax.BAD_STRING) and value.startswith(_COMMENT_STARTS + ("(",))


def _check_value(setting: Setting, analysis: Analysis, cat: Catalogue) -> None:
    parameter = setting.parameter
    line = setting.line
    kind = parameter.kind
    add_problem = setting.add_problem
    value_kind = line.value_kind
    text = line.value or ""
    unit = parameter.unit(analysis.axis_type)
    name = setting.canonical

    if value_kind == syntax.BAD_STRING:
        return  # reported as a syntax error (LIS001)
    if value_kind == syntax.REFERENCE:
        setting.value = _reference(setting, cat, analysis)
        return
    if value_kind is None or (text.startswith("(")):
        # No value at all, or a `(` comment right after the name.
        if kind in (STRING,):
            setting.value = ""
            return
        add_problem(ValueProblem("LIS201", f"`{name}` has no value; {_expected(parameter)} is expected"))
        return
    if comment_in_value_position(line):
        if kind in (STRING, SYMBOL):
            add_problem(
                ValueProblem(
                    "LIS007",
                    f"`{name}` is a string parameter: the CNC reads `{_value_and_rest(line)}` as its value, not as a comment "
                    f"(after a string only `(` starts a comment); to leave it empty write nothing after the name "
                    f"or start the comment with `(`",
                )
            )
        else:
            add_problem(ValueProblem("LIS201", f"`{name}` has no value (`{text}` starts a comment); {_expected(parameter)} is expected"))
        return

    if kind == BOOL:
        _check_bool(setting, text, value_kind)
    elif kind == INTEGER:
        _check_integer(setting, text, value_kind, unit)
    elif kind == REAL:
        _check_real(setting, text, value_kind, unit)
    elif kind == SYMBOL:
        _check_symbol(setting, text, value_kind)
    else:
        setting.value = text[1:-1] if value_kind == syntax.STRING else text
        if parameter.max_length is not None and len(setting.value) > parameter.max_length:
            add_problem(
                ValueProblem(
                    "LIS206",
                    f"`{name}` is {len(setting.value)} characters long; the CNC stores at most "
                    f"{parameter.max_length} characters for this parameter, shorten the value",
                )
            )
    textual = value_kind in (syntax.SYMBOL, syntax.STRING)
    if kind in (STRING, SYMBOL) and textual and line.rest is not None and not line.rest.startswith("("):
        add_problem(
            ValueProblem(
                "LIS007",
                f"text `{line.rest}` after the string value of `{name}` is not a `(` comment; the CNC reads it "
                f"as part of the value or rejects the line; start the comment with `(`",
                span="rest",
            )
        )


def _value_and_rest(line: syntax.Line) -> str:
    return (line.value or "") + line.sep2 + (line.rest or "")


def _expected(parameter: Parameter) -> str:
    kind = parameter.kind
    if kind == BOOL:
        return "0 or 1"
    if kind == INTEGER:
        return f"an integer ({parameter.type})"
    if kind == REAL:
        return "a number (REAL64)"
    if kind == SYMBOL:
        return "one of " + ", ".join(parameter.symbols)
    return "a string"


def _check_bool(setting: Setting, text: str, value_kind: str) -> None:
    parameter = setting.parameter
    name = setting.canonical
    if value_kind in (syntax.INT, syntax.HEX):
        number = _as_int(setting.line)
        if number in (0, 1):
            setting.value = bool(number)
            return
        setting.add_problem(
            ValueProblem("LIS201", f"`{name}` is BOOLEAN: write 0 (off) or 1 (on), not `{text}`",
                         replacement="1" if number else "0")
        )
        return
    if value_kind == syntax.SYMBOL:
        if text in ("TRUE", "FALSE"):
            setting.value = text == "TRUE"
            return
        if parameter.symbols and text in parameter.symbols:
            setting.value = parameter.symbols.index(text) == 1
            return
        if parameter.symbols:
            _unknown_symbol(setting, text)
            return
    setting.add_problem(
        ValueProblem("LIS201", f"`{name}` is BOOLEAN: write 0 (off) or 1 (on), not `{text}`")
    )


def _check_integer(setting: Setting, text: str, value_kind: str, unit: str | None) -> None:
    parameter = setting.parameter
    name = setting.canonical
    if value_kind in (syntax.INT, syntax.HEX):
        number = _as_int(setting.line)
        if isinstance(number, NumberProblem):
            _unusable_number(setting, text, number)
            return
        setting.value = number
        _check_range(setting, number, unit)
        return
    if value_kind == syntax.SYMBOL and parameter.symbols:
        if text in parameter.symbols:
            setting.value = parameter.symbol_codes.get(text, text)
            return
        _unknown_symbol(setting, text)
        return
    if value_kind == syntax.REAL:
        message = f"`{name}` is an integer parameter ({parameter.type}) but `{text}` is a real number"
        replacement = None
        as_float = parse_real(text)
        if isinstance(as_float, float) and as_float.is_integer():
            replacement = str(int(as_float))
            message += f"; write `{replacement}`"
        setting.add_problem(ValueProblem("LIS201", message, replacement))
        return
    setting.add_problem(
        ValueProblem("LIS201", f"`{name}` expects {_expected(parameter)}, not the text `{text}`")
    )


def _check_real(setting: Setting, text: str, value_kind: str, unit: str | None) -> None:
    if value_kind in (syntax.INT, syntax.HEX, syntax.REAL):
        number = parse_real(text)
        if isinstance(number, NumberProblem):
            _unusable_number(setting, text, number)
            return
        setting.value = number
        _check_range(setting, number, unit)
        return
    setting.add_problem(
        ValueProblem("LIS201", f"`{setting.canonical}` expects a number (REAL64), not the text `{text}`")
    )


def _check_range(setting: Setting, number: float, unit: str | None) -> None:
    parameter = setting.parameter
    name = setting.canonical
    if parameter.allowed:
        if number not in parameter.allowed and number != parameter.default:
            codes = ", ".join(str(a) for a in parameter.allowed)
            setting.add_problem(
                ValueProblem("LIS202", f"`{name}` = {number} is not an accepted value; accepted: {codes}")
            )
        return
    low, high = parameter.limits
    if parameter.strict_positive_real and number <= 0 and number != parameter.default:
        setting.add_problem(
            ValueProblem("LIS202", f"`{name}` = {describe(number, unit)} must be greater than 0")
        )
        return
    if low is not None and number < low:
        setting.add_problem(
            ValueProblem(
                "LIS202",
                f"`{name}` = {describe(number, unit)} is below the minimum {describe(low, unit)}"
                f"{_range_hint(parameter)}; use a value of at least {_plain(low)}",
            )
        )
    elif high is not None and number > high:
        setting.add_problem(
            ValueProblem(
                "LIS202",
                f"`{name}` = {describe(number, unit)} is above the maximum {describe(high, unit)}"
                f"{_range_hint(parameter)}; use a value of at most {_plain(high)}",
            )
        )


def _plain(value: float) -> str:
    return str(int(value)) if float(value).is_integer() else f"{value:g}"


def _range_hint(parameter: Parameter) -> str:
    text = parameter.range_text.split(";")[0].strip()
    if not text or text.startswith("("):
        return f" of {parameter.type}"
    return f" (manual range: {text})"


def _check_symbol(setting: Setting, text: str, value_kind: str) -> None:
    parameter = setting.parameter
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
    _unknown_symbol(setting, text)


def _unknown_symbol(setting: Setting, text: str) -> None:
    parameter = setting.parameter
    choices = list(parameter.symbols)
    match = difflib.get_close_matches(text, choices, n=1, cutoff=0.6)
    if not match:
        upper = [c for c in choices if c == text.upper()]
        match = upper
    message = f"`{text}` is not a value of `{setting.canonical}`"
    if match:
        message += f" (did you mean `{match[0]}`?)"
    message += "; accepted: " + ", ".join(choices)
    if parameter.symbol_codes:
        message += " (or their numbers " + ", ".join(str(c) for c in parameter.symbol_codes.values()) + ")"
    strong = difflib.get_close_matches(text, choices, n=2, cutoff=0.8)
    if not strong and match and match[0] == text.upper():
        strong = match
    # Only an unambiguous, close match is offered as a fix.
    replacement = strong[0] if len(strong) == 1 else None
    setting.add_problem(ValueProblem("LIS203", message, replacement=replacement))


def _reference(setting: Setting, cat: Catalogue, analysis: Analysis) -> Reference | None:
    parameter = setting.parameter
    name = setting.canonical
    reference = parse_reference(setting.line.value or "")
    if isinstance(reference, NumberProblem):
        setting.add_problem(ValueProblem("LIS205", f"`{name}` refers to `{setting.line.value}`, which {reference}"))
        return None
    target_id, index = reference.target, reference.index
    target = cat.by_id.get(target_id)
    if target is None:
        setting.add_problem(
            ValueProblem("LIS205", f"`{name}` refers to {target_id}, which is not an axis parameter")
        )
        return None
    if target.id == parameter.id:
        setting.add_problem(
            ValueProblem("LIS205", f"`{name}` refers to itself ({reference}); write a value instead")
        )
        return None
    if _category(target) != _category(parameter):
        setting.add_problem(
            ValueProblem(
                "LIS205",
                f"`{name}` ({parameter.type}) refers to {target_id} `{target.path}`, which is {target.type}; "
                f"a reference must name a parameter of the same kind",
            )
        )
        return None
    own_unit, target_unit = parameter.unit(analysis.axis_type), target.unit(analysis.axis_type)
    if own_unit != target_unit:
        setting.add_problem(
            ValueProblem(
                "LIS205",
                f"`{name}` is in {unit_label(own_unit) or 'no unit'} but refers to {target_id} `{target.path}` "
                f"in {unit_label(target_unit) or 'no unit'}; the CNC rejects references with different units",
            )
        )
        return None
    if index is not None and target.index_bounds:
        low, high = target.index_bounds[0]
        if not low <= index <= high:
            setting.add_problem(
                ValueProblem(
                    "LIS205",
                    f"`{name}` refers to {reference}, but {target_id} has indices {low}..{high} only",
                )
            )
            return None
    return reference


def _category(parameter: Parameter) -> str:
    return {BOOL: "bool", INTEGER: "number", REAL: "number"}.get(parameter.kind, "text")

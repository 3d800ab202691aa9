"""Numbers as a list writes them, turned into Python values: the one place that converts them.

Every function returns either the value or a `NumberProblem` saying why there is
none (too many digits, beyond the REAL64 range, not a number at all). None of
them raises, whatever the text: Python refuses to convert integers of more than
4,300 digits, turns `1e400` into infinity and cannot turn a 300-digit integer
into a float, and each of those used to end a run with an internal error.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass

# More significant digits than any integer type (UNS64 has 20) or array bound needs.
MAX_DIGITS = 30
# 64 bits: the widest integer type of the CNC.
MAX_HEX_DIGITS = 16
# Parameter ids have five digits; a few more are allowed so that `P-AXIS-000212` still reads.
MAX_ID_DIGITS = 8

_DECIMAL = re.compile(r"[+-]?[0-9]+")
_HEX = re.compile(r"([+-]?)0[xX]([0-9A-Fa-f]+)")
_REAL = re.compile(r"[+-]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][+-]?[0-9]+)?")
_REFERENCE = re.compile(r"P-AXIS-([0-9]+)(?:\.([0-9]+))?")


@dataclass(frozen=True, slots=True)
class NumberProblem:
    """Why a text is no usable number; `digits` counts the digits written."""

    reason: str  # "digits", "range" or "syntax"
    digits: int = 0
    detail: str = ""

    def __str__(self) -> str:
        if self.reason == "digits":
            return f"has {self.digits:,} digits{self.detail}"
        if self.reason == "range":
            return "is beyond the range of a 64-bit real number (about ±1.8e308)"
        return f"is not a number{self.detail}"


@dataclass(frozen=True, slots=True)
class Reference:
    """A value that names another parameter: `P-AXIS-00212.0`."""

    target: str
    index: int | None

    def __str__(self) -> str:
        return self.target if self.index is None else f"{self.target}.{self.index}"


def _too_long(digits: str, limit: int) -> NumberProblem | None:
    significant = len(digits.lstrip("0"))
    if significant > limit:
        return NumberProblem("digits", len(digits))
    return None


def parse_int(text: str) -> int | NumberProblem:
    """A signed decimal integer (`-2025000`)."""
    if len(text) <= MAX_DIGITS and text.isascii() and text.isdigit():  # most are: no pattern, no count
        return int(text)
    if not _DECIMAL.fullmatch(text):
        return NumberProblem("syntax")
    return _too_long(text.lstrip("+-"), MAX_DIGITS) or int(text)


def parse_hex(text: str) -> int | NumberProblem:
    """A hexadecimal integer (`0x400001`, optionally signed), at most 64 bits of digits."""
    match = _HEX.fullmatch(text)
    if match is None:
        return NumberProblem("syntax")
    sign, digits = match.groups()
    problem = _too_long(digits, MAX_HEX_DIGITS)
    if problem is not None:
        return NumberProblem("digits", problem.digits, " (a 64-bit value has at most 16 hexadecimal digits)")
    value = int(digits, 16)
    return -value if sign == "-" else value


def parse_integer(text: str) -> int | NumberProblem:
    """A decimal or hexadecimal integer, whichever the text is."""
    return parse_hex(text) if _HEX.fullmatch(text) else parse_int(text)


def parse_real(text: str) -> float | NumberProblem:
    """A decimal, E-notation or hexadecimal number as a finite 64-bit float."""
    if _HEX.fullmatch(text):
        whole = parse_hex(text)
        return whole if isinstance(whole, NumberProblem) else float(whole)
    if not _REAL.fullmatch(text):
        return NumberProblem("syntax")
    value = float(text)  # no digit limit for floats: long mantissas only round
    return value if math.isfinite(value) else NumberProblem("range")


def parse_reference(text: str) -> Reference | NumberProblem:
    """`P-AXIS-00212` or `P-AXIS-00212.0`: the id normalised to five digits and the index."""
    match = _REFERENCE.fullmatch(text)
    if match is None:
        return NumberProblem("syntax", detail=" (a reference is written P-AXIS-nnnnn or P-AXIS-nnnnn.i)")
    number, index = match.groups()
    problem = _too_long(number, MAX_ID_DIGITS)
    if problem is not None:
        return NumberProblem("digits", problem.digits, " in the parameter id (ids have five)")
    position: int | None = None
    if index is not None:
        parsed = parse_int(index)
        if isinstance(parsed, NumberProblem):
            return NumberProblem("digits", parsed.digits, " in the index")
        position = parsed
    return Reference(f"P-AXIS-{int(number):05d}", position)


def as_float(value: object) -> float | None:
    """A finite float for an int or float, or None when it has none (too large, infinite, not a number)."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return None
    try:
        converted = float(value)
    except OverflowError:
        return None
    return converted if math.isfinite(converted) else None

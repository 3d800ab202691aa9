"""Units: list units as the catalogue names them, and the same value for people.

The model keeps values in list units (0.1 µm, µm/s, 0.0001°, ...). Conversion
to mm, mm/s, m/min or degrees happens here and only for display, and in the
dry-run engine's boundary.
"""

from __future__ import annotations

import math

from ..syntax.numbers import as_float

# catalogue unit -> (display name, factor to the human unit, human unit)
_UNITS: dict[str, tuple[str, float, str]] = {
    "0.1um": ("0.1 µm", 1e-4, "mm"),
    "um": ("µm", 1e-3, "mm"),
    "mm": ("mm", 1.0, "mm"),
    "um/s": ("µm/s", 1e-3, "mm/s"),
    "0.0001deg": ("0.0001°", 1e-4, "°"),
    "0.001deg": ("0.001°", 1e-3, "°"),
    "deg": ("°", 1.0, "°"),
    "0.001deg/s": ("0.001°/s", 1e-3, "°/s"),
    "mm/s^2": ("mm/s²", 1.0, "mm/s²"),
    "deg/s^2": ("°/s²", 1.0, "°/s²"),
    "mm/s^3": ("mm/s³", 1.0, "mm/s³"),
    "deg/s^3": ("°/s³", 1.0, "°/s³"),
    "us": ("µs", 1e-3, "ms"),
    "ms": ("ms", 1.0, "ms"),
    "s": ("s", 1.0, "s"),
    "0.1%": ("0.1 %", 0.1, "%"),
    "%": ("%", 1.0, "%"),
    "0.1um/rev": ("0.1 µm/rev", 1e-4, "mm/rev"),
    "0.0001deg/rev": ("0.0001°/rev", 1e-4, "°/rev"),
}


def unit_label(unit: str | None) -> str:
    if not unit:
        return ""
    return _UNITS.get(unit, (unit, 1.0, unit))[0]


# Significant digits: a value in list units and its exact decimal conversion keep all that a float
# holds (1234.5678 mm, not 1235 mm); derived everyday forms (m/min, rpm) are approximations.
_EXACT = 12
_ABOUT = 4


def _number(value: float, significant: int = _EXACT) -> str:
    """`value` in plain decimal notation (never `6e-05`), at most `significant` significant digits."""
    number = as_float(value)
    if number is None:  # an integer too large for a float, or inf / nan from elsewhere
        if isinstance(value, int) and not isinstance(value, bool):
            return f"a number of about {int(value.bit_length() * math.log10(2)) + 1:,} digits"
        return str(value)
    if number.is_integer() and abs(number) < 1e15:
        return str(int(number))
    if number == 0:
        return "0"
    exponent = math.floor(math.log10(abs(number)))
    if not -12 <= exponent < 15:  # far outside what a list holds: plain notation would be unreadable
        return f"{number:.{significant}g}"
    text = f"{number:.{max(significant - 1 - exponent, 0)}f}"
    if "." in text:
        text = text.rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


def to_human(value: object, unit: str | None) -> str | None:
    """`20000, "um/s"` -> `20 mm/s = 1.2 m/min`; None when there is nothing to add (not a number, no unit)."""
    if unit not in _UNITS or not isinstance(value, (int, float)) or isinstance(value, bool):
        return None
    label, factor, human = _UNITS[unit]
    number = as_float(value)
    if number is None or (factor == 1.0 and human == label):
        return None
    converted = number * factor
    text = f"{_number(converted)} {human}"
    if human == "mm/s":
        text += f" = {_number(converted * 60 / 1000, _ABOUT)} m/min"
    elif human == "°/s":
        text += f" = {_number(converted / 6, _ABOUT)} rpm"
    elif human == "ms" and abs(converted) >= 1000:
        text = f"{_number(converted / 1000)} s"
    return text


def describe(value: object, unit: str | None) -> str:
    """A value with its list unit and, where useful, its human form (anything but a number as `str` shows it).

    `20000, "um/s"` -> `20000 µm/s (= 20 mm/s = 1.2 m/min)`;
    `1500, "0.1%"` -> `1500 [0.1 %] (= 150 %)`.
    """
    if not isinstance(value, (int, float)):
        return str(value)
    label = unit_label(unit)
    if not label:
        return _number(value)
    text = f"{_number(value)} [{label}]" if label[0].isdigit() else f"{_number(value)} {label}"
    human = to_human(value, unit) if value else None
    return f"{text} (= {human})" if human else text

"""`achslint diff A B`: how two lists differ in what the CNC ends up with.

Both lists are read the way the CNC loads them (built-in defaults, then an
optional default list, then the list), so formatting, comments, old names,
hex or decimal spelling and assignments that repeat the default make no
difference. The result lists every parameter whose effective value differs,
with units.
"""

from __future__ import annotations

from typing import TypedDict

from .axis.resolved import ResolvedAxis, plain, resolve_bytes
from .catalogue.units import to_human, unit_label


class Difference(TypedDict):
    """A parameter whose effective value differs (`a`, `b`: the values, booleans as 0/1)."""

    parameter: str
    p_axis: str
    a: int | float | str | None
    b: int | float | str | None
    unit: str | None
    a_human: str | None
    b_human: str | None
    a_source: str
    b_source: str


class UnknownDifference(TypedDict):
    """A parameter the catalogue does not know, written differently (None: not written in that list)."""

    parameter: str
    a: str | None
    b: str | None


class DiffReport(TypedDict):
    """What `achslint diff --format json` prints."""

    version: int
    a: str
    b: str
    differences: list[Difference]
    unknown_parameters: list[UnknownDifference]


def _values(data: bytes, name: str, defaults: bytes | None) -> ResolvedAxis:
    return resolve_bytes(data, name, defaults)


def _unknown(axis: ResolvedAxis) -> dict[str, str]:
    """The written value of each parameter the catalogue does not know, by its name as written."""
    return {s.line.path: s.line.value or "" for s in axis.analysis.settings if not s.known and s.line.path}


def diff_lists(a: bytes, a_name: str, b: bytes, b_name: str, defaults: bytes | None = None) -> DiffReport:
    left, right = _values(a, a_name, defaults), _values(b, b_name, defaults)
    paths = sorted(set(left.set_paths()) | set(right.set_paths()))
    rows: list[Difference] = []
    for path in paths:
        before, after = left.get(path), right.get(path)
        if before == after:
            continue
        parameter = left.parameter(path)
        unit = parameter.unit(right.axis_type)
        rows.append(
            {
                "parameter": path,
                "p_axis": parameter.id,
                "a": plain(before),
                "b": plain(after),
                "unit": unit_label(unit) or None,
                "a_human": to_human(before, unit)
                if isinstance(before, (int, float)) and not isinstance(before, bool)
                else None,
                "b_human": to_human(after, unit)
                if isinstance(after, (int, float)) and not isinstance(after, bool)
                else None,
                "a_source": str(left.origin(path)),
                "b_source": str(right.origin(path)),
            }
        )
    unknown_a, unknown_b = _unknown(left), _unknown(right)
    unknown: list[UnknownDifference] = [
        {"parameter": path, "a": unknown_a.get(path), "b": unknown_b.get(path)}
        for path in sorted(set(unknown_a) | set(unknown_b))
        if unknown_a.get(path) != unknown_b.get(path)
    ]
    return {"version": 1, "a": a_name, "b": b_name, "differences": rows, "unknown_parameters": unknown}

"""`achslint diff A B`: how two lists differ in what the CNC ends up with.

Both lists are read the way the CNC loads them (built-in defaults, then an
optional default list, then the list, then the CNC's load-time corrections), so
formatting, comments, old names, hex or decimal spelling and assignments that
repeat the default make no difference. The result lists every parameter whose
effective value differs, with units, and every parameter written differently
that the CNC corrects to the same effective value ("written differs, effective
same": the lists differ although the axis runs the same).

`compare_axes` is the one comparison of two resolved axes; the machine diff
(`machinediff`) runs it for every axis the two machines share.
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


class WrittenDifference(TypedDict):
    """A parameter written differently that the CNC corrects to one effective value `used`; `a_error` /
    `b_error`: the CNC message of the correction on that side (None: that side is used as written)."""

    parameter: str
    p_axis: str
    a: int | float | str | None
    b: int | float | str | None
    used: int | float | str | None
    unit: str | None
    a_human: str | None
    b_human: str | None
    used_human: str | None
    a_error: str | None
    b_error: str | None
    a_source: str
    b_source: str


class UnknownDifference(TypedDict):
    """A parameter the catalogue does not know, written differently (None: not written in that list)."""

    parameter: str
    a: str | None
    b: str | None


class Comparison(TypedDict):
    """How two resolved axes differ: effective values, written values only, unknown parameters."""

    differences: list[Difference]
    written_differences: list[WrittenDifference]
    unknown_parameters: list[UnknownDifference]


class DiffReport(Comparison):
    """What `achslint diff --format json` prints for two lists."""

    version: int
    a: str
    b: str


def _unknown(axis: ResolvedAxis) -> dict[str, str]:
    """The written value of each parameter the catalogue does not know, by its name as written."""
    return {s.line.path: s.line.value or "" for s in axis.analysis.settings if not s.known and s.line.path}


def _compared_paths(axis: ResolvedAxis) -> set[str]:
    """The parameters whose value can differ from the built-in default: those assigned in the list or
    the default list, and those the CNC corrects (a correction can follow from another parameter)."""
    return set(axis.set_paths()) | {correction.parameter for correction in axis.corrections}


def _error(axis: ResolvedAxis, path: str) -> str | None:
    correction = axis.correction(path)
    return correction.error if correction is not None else None


def compare_axes(left: ResolvedAxis, right: ResolvedAxis) -> Comparison:
    """Every parameter whose effective value (`get`) differs, then every one whose written value differs
    while the effective values agree, then the unknown parameters written differently. Units are those of
    `right`'s axis type."""
    differences: list[Difference] = []
    written: list[WrittenDifference] = []
    for path in sorted(_compared_paths(left) | _compared_paths(right)):
        before, after = left.get(path), right.get(path)
        written_before, written_after = left.written(path), right.written(path)
        if before == after and written_before == written_after:
            continue
        parameter = left.parameter(path)
        unit = parameter.unit(right.axis_type)
        label = unit_label(unit) or None
        if before != after:
            differences.append(
                {
                    "parameter": path,
                    "p_axis": parameter.id,
                    "a": plain(before),
                    "b": plain(after),
                    "unit": label,
                    "a_human": to_human(before, unit),
                    "b_human": to_human(after, unit),
                    "a_source": str(left.origin(path)),
                    "b_source": str(right.origin(path)),
                }
            )
            continue
        written.append(
            {
                "parameter": path,
                "p_axis": parameter.id,
                "a": plain(written_before),
                "b": plain(written_after),
                "used": plain(after),
                "unit": label,
                "a_human": to_human(written_before, unit),
                "b_human": to_human(written_after, unit),
                "used_human": to_human(after, unit),
                "a_error": _error(left, path),
                "b_error": _error(right, path),
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
    return {"differences": differences, "written_differences": written, "unknown_parameters": unknown}


def differ(comparison: Comparison) -> bool:
    """Whether a comparison found anything (the exit code of `diff`)."""
    return bool(
        comparison["differences"] or comparison["written_differences"] or comparison["unknown_parameters"]
    )


def diff_lists(
    a: bytes,
    a_name: str,
    b: bytes,
    b_name: str,
    defaults: bytes | None = None,
    *,
    a_defaults: bytes | None = None,
    b_defaults: bytes | None = None,
    defaults_name: str = "default list",
) -> DiffReport:
    """Two axis lists compared. `defaults`: the default list loaded under both (`defaults_name`: its name, in
    the sources of its values); `a_defaults` / `b_defaults`: one loaded under that list alone instead (the
    report's backup may come from another machine)."""
    left = resolve_bytes(a, a_name, a_defaults if a_defaults is not None else defaults, defaults_name)
    right = resolve_bytes(b, b_name, b_defaults if b_defaults is not None else defaults, defaults_name)
    comparison = compare_axes(left, right)
    return {"version": 1, "a": a_name, "b": b_name, **comparison}

"""`achslint diff A B` as text or JSON.

Two lists (`listdiff.diff_lists`): the parameters whose effective values differ, with units and where each
value came from, then those written differently that the CNC corrects to the same value, then the unknown
parameters that differ. Two machines (`machinediff.diff_machines`): per axis the same rows and its homing
strategy, then each channel's names and coupled pairs. The JSON of either is the report itself.
"""

from __future__ import annotations

from collections import Counter
from typing import TYPE_CHECKING

from . import Screen, write_json

if TYPE_CHECKING:
    from ..listdiff import Comparison, DiffReport, WrittenDifference
    from ..machinediff import AxisDiff, AxisSide, ChannelDiff, ChannelName, ListDiff, MachineDiffReport
    from . import Registry

WRITTEN_ONLY = "written differs, effective same"


def _written_line(row: WrittenDifference) -> str:
    """`getriebe[0].vb_refmax (P-AXIS-00217): written differs, effective same: 5000 → 4000 µm/s, the CNC uses
    3000 µm/s (= 3 mm/s …) in both (A: P-ERR-110421, B: P-ERR-110421)`."""
    unit = f" {row['unit']}" if row["unit"] else ""
    used = f"{row['used']}{unit}" + (f" (= {row['used_human']})" if row["used_human"] else "")
    corrected = [
        f"{side}: {error}" for side, error in (("A", row["a_error"]), ("B", row["b_error"])) if error
    ]
    why = f" ({', '.join(corrected)})" if corrected else ""
    return (
        f"{row['parameter']} ({row['p_axis']}): {WRITTEN_ONLY}: {row['a']} → {row['b']}{unit}, "
        f"the CNC uses {used} in both{why}"
    )


def _rows(comparison: Comparison, screen: Screen, indent: str = "") -> None:
    """The rows of one comparison: a table of effective differences, then one line per other row."""
    from rich.table import Table

    console = screen.console
    if comparison["differences"]:
        table = Table(title_justify="left")
        for column in ("parameter", "id", "A", "B", "unit", "A human", "B human", "A from", "B from"):
            table.add_column(column, overflow="fold")
        for row in comparison["differences"]:
            table.add_row(
                row["parameter"],
                row["p_axis"],
                str(row["a"]),
                str(row["b"]),
                row["unit"] or "",
                row["a_human"] or "",
                row["b_human"] or "",
                row["a_source"],
                row["b_source"],
            )
        console.print(table)
    for written in comparison["written_differences"]:
        screen.echo(indent + _written_line(written))
    for unknown in comparison["unknown_parameters"]:
        screen.echo(f"{indent}unknown parameter {unknown['parameter']}: {unknown['a']!r} → {unknown['b']!r}")


def as_text(report: DiffReport, screen: Screen) -> None:
    """One line when the lists configure the axis alike; otherwise a table, one row per difference."""
    if not (report["differences"] or report["written_differences"] or report["unknown_parameters"]):
        screen.echo(f"{report['a']} and {report['b']} configure the axis the same way")
        return
    screen.echo(f"{report['a']} → {report['b']}")
    _rows(report, screen)


RENDERERS: Registry[DiffReport] = {"text": as_text, "json": write_json}


# -- two machines -------------------------------------------------------------------------------------


def _axis_title(side: AxisSide) -> str:
    return f"{side['logical_number']} {side['name']}" if side["name"] else str(side["logical_number"])


def _axis_name(side: AxisSide) -> str:
    return f"axis {_axis_title(side)} ({side['entry']} {side['list']})"


def _axis_text(row: AxisDiff, screen: Screen) -> None:
    a, b = row["a"], row["b"]
    if a is None and b is not None:
        screen.echo(f"+ {_axis_name(b)}: only in B")
        return
    if b is None and a is not None:
        screen.echo(f"- {_axis_name(a)}: only in A")
        return
    assert a is not None and b is not None
    screen.echo(
        f"~ axis {_axis_title(a)}: A {a['entry']} {a['list']}, B {b['entry']} {b['list']} (paired by "
        f"{row['matched_by']})"
    )
    if (a["logical_number"], a["name"]) != (b["logical_number"], b["name"]):
        screen.echo(f"    renumbered or renamed: axis {_axis_title(a)} → axis {_axis_title(b)}")
    if row["homing_differs"]:
        screen.echo(
            f"    homing strategy: {a['homing']} ({a['homing_title']}) → {b['homing']} ({b['homing_title']})"
        )
    _rows(row, screen, "    ")


def _mapped(name: ChannelName | None) -> str:
    if name is None:
        return "—"
    return f"{'spindle' if name['spindle'] else 'logical axis'} {name['logical_number']}"


def _channel_text(row: ChannelDiff, screen: Screen) -> None:
    lists = {"added": f"only in B ({row['b_list']})", "removed": f"only in A ({row['a_list']})"}
    screen.echo(
        f"channel {row['channel']} (sda_mds[{row['channel'] - 1}]): {lists.get(row['status'], 'changed')}"
    )
    for name in row["names"]:
        screen.echo(f"    {name['name']}: {_mapped(name['a'])} → {_mapped(name['b'])}")
    for pair in row["pairs"]:
        screen.echo(
            f"    coupled pair master {pair['master']} / slave {pair['slave']}: only in {pair['only_in'].upper()}"
        )


def list_title(row: ListDiff) -> str:
    """How a list row is named: `the start-up list's own settings`, or `werkz_data[0] (tool data list)`."""
    if row["entry"] == "startup":
        return "the start-up list's own settings"
    from ..catalogue.kinds import BY_ID

    kind = BY_ID.get(row["kind"])
    return f"{row['entry']} ({kind.name if kind is not None else 'list'})"


def _list_text(row: ListDiff, screen: Screen) -> None:
    lists = {"added": f"only in B ({row['b_list']})", "removed": f"only in A ({row['a_list']})"}
    screen.echo(f"{list_title(row)}: {lists.get(row['status'], 'changed')}")
    for change in row["changes"]:
        a = "not written" if change["a"] is None else change["a"]
        b = "not written" if change["b"] is None else change["b"]
        screen.echo(f"    {change['parameter']}: {a} → {b}")


def _count(number: int, one: str, many: str) -> str:
    return f"{number} {one if number == 1 else many}"


def machines_as_text(report: MachineDiffReport, screen: Screen) -> None:
    """One line when the machines are the same; otherwise each axis and channel that differs."""
    a, b = report["a"]["startup"], report["b"]["startup"]
    axes, channels = report["axes"], report["channels"]
    if not report["differ"]:
        count = sum(row["entry"] != "startup" for row in report["lists"])
        others = f", {_count(count, 'list of another kind', 'lists of other kinds')}" if count else ""
        screen.echo(
            f"no difference: {a} and {b} load the same machine ({_count(len(axes), 'axis', 'axes')}, "
            f"{_count(len(channels), 'channel', 'channels')}{others})"
        )
        return
    screen.echo(f"A: {a} (CNC root {report['a']['cnc_root']})")
    screen.echo(f"B: {b} (CNC root {report['b']['cnc_root']})")
    ways = Counter(row["matched_by"] for row in axes if row["matched_by"])
    paired = ", ".join(f"{count} by {how}" for how, count in ways.items()) or "none"
    screen.echo(
        f"axes in both: {paired}; "
        f"{sum(row['a'] is None for row in axes)} only in B, {sum(row['b'] is None for row in axes)} only in A"
    )
    for row in axes:
        if row["status"] != "same":
            _axis_text(row, screen)
    for channel in channels:
        if channel["status"] != "same":
            _channel_text(channel, screen)
    for listed in report["lists"]:
        if listed["status"] != "same":
            _list_text(listed, screen)


MACHINE_RENDERERS: Registry[MachineDiffReport] = {"text": machines_as_text, "json": write_json}

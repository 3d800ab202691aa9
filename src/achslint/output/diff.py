"""`achslint diff A B` as text or JSON: the parameters whose effective values differ, with units and where
each value came from, then the unknown parameters that differ. The report is `listdiff.diff_lists`'s; its
JSON is the report itself."""

from __future__ import annotations

from typing import TYPE_CHECKING

from . import Screen, write_json

if TYPE_CHECKING:
    from ..listdiff import DiffReport
    from . import Registry


def as_text(report: DiffReport, screen: Screen) -> None:
    """One line when the lists configure the axis alike; otherwise a table, one row per difference."""
    from rich.table import Table

    console = screen.console
    if not report["differences"] and not report["unknown_parameters"]:
        console.print(f"{report['a']} and {report['b']} configure the axis the same way")
        return
    table = Table(title=f"{report['a']} → {report['b']}", title_justify="left")
    for column in ("parameter", "id", "A", "B", "unit", "A human", "B human", "A from", "B from"):
        table.add_column(column, overflow="fold")
    for row in report["differences"]:
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
    for unknown in report["unknown_parameters"]:
        console.print(f"unknown parameter {unknown['parameter']}: {unknown['a']!r} → {unknown['b']!r}")


RENDERERS: Registry[DiffReport] = {"text": as_text, "json": write_json}
